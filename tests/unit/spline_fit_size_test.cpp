// SPDX-License-Identifier: Apache-2.0
// A spline fit's size is known before it starts (SplineFitOptions::fit_memory_bytes(), refused in
// validate() above kMaxFitMemory): the refusals name the options and come before any sampling,
// a box beyond the validated lateral range is refused by the option table, and the estimate is an
// upper bound of what a fit really takes (the growth of this process's peak resident memory
// during a fit; each CTest test runs in a process of its own).
#include <gtest/gtest.h>

#include <sys/resource.h>

#include <chrono>
#include <iostream>
#include <string>

#include "spline_test_model.hpp"

namespace wrc {
namespace {

std::string refusal(const SplineFitOptions& o) {
  try {
    o.validate();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(SplineFitSize, TooFineASamplingIsRefusedNamingTheOptions) {
  for (const double step : {1e-7, 1e-9, 1e-300}) {
    SplineFitOptions o;
    o.sample_step_y = step;
    const auto t0 = std::chrono::steady_clock::now();
    const std::string why = refusal(o);
    std::cout << "[ measured ] refused in " << std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count()
              << " s: " << why << "\n";
    EXPECT_NE(why.find("(--sample-step)"), std::string::npos) << why;
    EXPECT_NE(why.find("GiB; a fit may take at most 1 GiB"), std::string::npos) << why;
    EXPECT_THROW(fit_spline_geometry(*test::s1002_uic60_geometry(), o), std::invalid_argument);
  }
  SplineFitOptions o;
  o.roll_samples = o.yaw_samples = 101;
  o.sample_step_y = 2e-5;
  EXPECT_NE(refusal(o).find("101 x 101 lines (--samples)"), std::string::npos) << refusal(o);
}

TEST(SplineFitSize, ABoxBeyondTheValidatedRangeIsRefused) {
  SplineFitOptions o;
  o.y_min = -1e300;
  o.y_max = 1e300;
  const std::string why = refusal(o);
  EXPECT_NE(why.find("y_min"), std::string::npos) << why;
  o.y_min = -0.05;
  o.y_max = 0.051;
  EXPECT_NE(refusal(o).find("y_max"), std::string::npos) << refusal(o);
}

// The default model's estimate is tens of megabytes (9801 samples per wheel), and a fit of the
// quick test model grows the peak resident memory by no more than its estimate.
TEST(SplineFitSize, TheEstimateBoundsWhatAFitTakes) {
  const SplineFitOptions defaults;
  EXPECT_LT(defaults.fit_memory_bytes(), 100e6);
  EXPECT_GT(defaults.fit_memory_bytes(), 9801.0 * 2 * sizeof(WheelSample));
  const SplineFitOptions quick = test::quick_spline_options();
  const auto geometry = test::s1002_uic60_geometry();
  rusage before{}, after{};
  ::getrusage(RUSAGE_SELF, &before);
  const SplineFit fit = fit_spline_geometry(*geometry, quick);
  ::getrusage(RUSAGE_SELF, &after);
  const double grown = (after.ru_maxrss - before.ru_maxrss) * 1024.0;  // ru_maxrss in kB
  std::cout << "[ measured ] peak resident memory grew by " << grown / 1e6 << " MB during the fit; estimate "
            << quick.fit_memory_bytes() / 1e6 << " MB\n";
  ASSERT_TRUE(fit.model);
  EXPECT_LE(grown, quick.fit_memory_bytes());
}

}  // namespace
}  // namespace wrc
