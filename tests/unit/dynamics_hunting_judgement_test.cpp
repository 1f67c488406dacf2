// SPDX-License-Identifier: Apache-2.0
// The judgement of a hunting run (judge_hunting, core/dynamics/hunting_run.hpp;
// docs/bifurcation.md, "One run") on synthetic samples whose cycles are known: a regular decay, a
// regular growth, a constant cycle, and motion whose cycles differ while its envelope holds (the
// flange-contact motion of a bogie at high speed, which a judgement by its last three cycles called
// decaying or growing at random).
//
// Sampling as a hunting run samples: every 1 ms; 11 Hz, the Cooperrider bogie's hunting frequency
// in flange contact. Default settings: window 2 s, tolerance 1 % per cycle.

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "core/dynamics/hunting_run.hpp"
#include "core/dynamics/simulation.hpp"

namespace wrc {
namespace {

constexpr double kFrequency = 11.0;  // [Hz]
constexpr double kStep = 1e-3;       // [s]

// y(t) = drift t + a_k sin(2 pi f t) in the k-th cycle, a_k = amplitude(k); yaw and contact angle 0.
template <class Amplitude>
HuntingSamples samples(double t_end, Amplitude amplitude, double frequency = kFrequency, double drift = 0.0) {
  HuntingSamples s;
  for (long i = 0; i * kStep <= t_end + 1e-12; ++i) {
    const double t = i * kStep;
    const long cycle = static_cast<long>(std::floor(t * frequency));
    s.t.push_back(t);
    s.y.push_back(drift * t + amplitude(cycle) * std::sin(2 * M_PI * frequency * t));
    s.yaw.push_back(0.0);
    s.angle.push_back(0.0);
  }
  return s;
}

// Cycle amplitudes between 3 and 4.5 mm in a fixed irregular order, repeating every 10 cycles
// (0.9 s): the largest, 4.5 mm, recurs in every window of 2 s.
double irregular_amplitude(long k) {
  static const double pattern[] = {4.5e-3, 3.2e-3, 3.9e-3, 3.0e-3, 4.1e-3, 3.6e-3, 4.4e-3, 3.3e-3, 3.8e-3, 3.1e-3};
  return pattern[k % 10];
}

TEST(HuntingJudgement, CyclesThatDifferUnderAHeldEnvelopeAreIrregularAndPersist) {
  const HuntingSettings settings;
  const double now = 6.0;
  const HuntingSamples s = samples(now, irregular_amplitude);
  HuntingRun r;
  judge_hunting(s, now, settings, r);
  // Cycle k lasts from k / f to (k + 1) / f, its crest and trough inside it: at 6 s the last
  // complete cycles are 62..65 (3.9, 3.0, 4.1, 3.6 mm), growth (3.6 / 3.9)^(1/3) = 0.974, which
  // the cycles alone judge decaying.
  EXPECT_NEAR(r.cycle.growth, std::cbrt(3.6 / 3.9), 1e-3);
  EXPECT_EQ(r.state, HuntingState::kIrregular) << hunting_state_name(r.state);
  EXPECT_TRUE(r.persists());
  // Both windows hold a 4.5 mm cycle: the envelope, the largest cycle, is 4.5 mm (its crest and
  // trough refined by the parabola through three samples) and holds exactly.
  EXPECT_NEAR(r.envelope, 4.5e-3, 4.5e-3 * 6e-4);
  EXPECT_NEAR(r.envelope_growth, 1.0, 1e-3);
  EXPECT_DOUBLE_EQ(r.amplitude(), r.envelope);

  // Before the run holds two windows the envelope has nothing to compare with: the cycles decide.
  HuntingRun early;
  judge_hunting(s, 3.0, settings, early);
  EXPECT_EQ(early.envelope_growth, 0.0);
  EXPECT_NE(early.state, HuntingState::kIrregular) << hunting_state_name(early.state);
}

// A regular decay shows in the envelope as in the cycles: decaying, the envelope's growth per cycle
// the cycles' (0.97) to the sampling of the crests (1e-3).
TEST(HuntingJudgement, ARegularDecayIsDecayingByItsEnvelopeToo) {
  const HuntingSettings settings;
  const double now = 6.0;
  const HuntingSamples s = samples(now, [](long k) { return 5e-3 * std::pow(0.97, static_cast<double>(k)); });
  HuntingRun r;
  judge_hunting(s, now, settings, r);
  EXPECT_EQ(r.state, HuntingState::kDecaying) << hunting_state_name(r.state);
  EXPECT_NEAR(r.cycle.growth, 0.97, 1e-3);
  EXPECT_NEAR(r.envelope_growth, 0.97, 1e-3);
  EXPECT_FALSE(r.persists());
}

// The envelope's growth is per period elapsed: at 10.3 Hz a window of 2 s holds 20.6 periods, and
// the largest cycles of two windows lie 20 or 21 cycles apart, so the growth per period comes out
// as 0.97^(20/20.6) or 0.97^(21/20.6), within 0.0015 of 0.97 (tolerance 2e-3). A slow drift of the
// mean (2 mm/s, as a body's sway would) leaves it alone: the envelope is the largest cycle's half
// peak-to-peak, not the window's range, which the drift would hold up (4 mm over a window against
// cycles of 0.5 to 2 mm) into an irregular judgement.
TEST(HuntingJudgement, TheEnvelopeGrowsPerPeriodAndIgnoresADriftOfTheMean) {
  const HuntingSettings settings;
  const double now = 6.0;
  HuntingRun r;
  judge_hunting(samples(now, [](long k) { return 5e-3 * std::pow(0.97, static_cast<double>(k)); }, 10.3, 2e-3), now,
                settings, r);
  EXPECT_EQ(r.state, HuntingState::kDecaying) << hunting_state_name(r.state);
  EXPECT_NEAR(r.envelope_growth, 0.97, 2e-3);
  EXPECT_LT(r.cycle.growth, 0.99);  // the cycles decay too (their half peak-to-peak carries a
                                    // drift of drift / (4 f) = 49 um, so not exactly 0.97)
}

// Samples after the time judged do not count: the same signal judged at 3 s with samples up to 6 s
// and with samples up to 3 s alone gives the same judgement.
TEST(HuntingJudgement, OnlySamplesUpToTheTimeJudgedCount) {
  const HuntingSettings settings;
  auto decay = [](long k) { return 5e-3 * std::pow(0.97, static_cast<double>(k)); };
  HuntingRun longer, exact;
  judge_hunting(samples(6.0, decay), 3.0, settings, longer);
  judge_hunting(samples(3.0, decay), 3.0, settings, exact);
  EXPECT_EQ(longer.cycle.cycles, exact.cycle.cycles);
  EXPECT_DOUBLE_EQ(longer.cycle.amplitude, exact.cycle.amplitude);
  EXPECT_DOUBLE_EQ(longer.envelope, exact.envelope);
  EXPECT_EQ(longer.state, exact.state);
}

TEST(HuntingJudgement, ARegularGrowthIsGrowingAndAConstantCycleALimitCycle) {
  const HuntingSettings settings;
  const double now = 6.0;
  HuntingRun growing, constant;
  judge_hunting(samples(now, [](long k) { return 1e-5 * std::pow(1.03, static_cast<double>(k)); }), now, settings,
                growing);
  EXPECT_EQ(growing.state, HuntingState::kGrowing) << hunting_state_name(growing.state);
  EXPECT_NEAR(growing.envelope_growth, 1.03, 1e-3);
  judge_hunting(samples(now, [](long) { return 4e-3; }), now, settings, constant);
  EXPECT_EQ(constant.state, HuntingState::kLimitCycle) << hunting_state_name(constant.state);
  EXPECT_NEAR(constant.cycle.amplitude, 4e-3, 4e-3 * 6e-4);
  EXPECT_DOUBLE_EQ(constant.amplitude(), constant.cycle.amplitude);
}

// A run that steps 1 ms at a time and samples the signal y(t) into the samples follow_hunting
// judges: the loop's settling without an integrator.
class SampledSignal final : public Simulation {
 public:
  SampledSignal(std::function<double(double)> y, double t_end, HuntingSamples& samples)
      : y_(std::move(y)), t_end_(t_end), samples_(samples) {}
  void start() override { sample(); }
  bool advance() override {
    if (t_ + 0.5 * kStep >= t_end_) {
      state_ = RunState::kFinished;
      return false;
    }
    t_ += kStep;
    sample();
    return true;
  }
  void request_stop() override {}
  void request_swap(std::shared_ptr<ContactEvaluator>) override {}
  void schedule_swap(double, std::shared_ptr<ContactEvaluator>) override {}
  RunState state() const override { return state_; }
  const std::string& message() const override { return message_; }
  double time() const override { return t_; }
  std::string model() const override { return "signal"; }
  RunCounters counters() const override { return {}; }
  const std::vector<SwapRecord>& swaps() const override { return swaps_; }

 private:
  void sample() {
    samples_.t.push_back(t_);
    samples_.y.push_back(y_(t_));
    samples_.yaw.push_back(0.0);
    samples_.angle.push_back(0.0);
  }
  std::function<double(double)> y_;
  double t_end_;
  HuntingSamples& samples_;
  double t_ = 0;
  RunState state_ = RunState::kRunning;
  std::string message_;
  std::vector<SwapRecord> swaps_;
};

// The cycle amplitudes of irregular_amplitude() times decay^k, at 11 Hz.
std::function<double(double)> irregular(double decay) {
  return [decay](double t) {
    const long k = static_cast<long>(std::floor(t * kFrequency));
    return irregular_amplitude(k) * std::pow(decay, static_cast<double>(k)) * std::sin(2 * M_PI * kFrequency * t);
  };
}

// The loop settles an irregular motion once its envelope has held at every judgement over a whole
// window: the first judgement with two windows behind it is at 4 s, the window 2 s, so it stops at
// 6 s of a run allowed 20 s, and it persists. The same motion dying at 1.5 % per cycle (its
// envelope by 0.985^20.6 = 0.73 per window) is no irregular motion at any judgement: it runs to
// its end and is judged decaying.
TEST(HuntingJudgement, AnIrregularMotionSettlesOnceItsEnvelopeHeldOverAWindow) {
  HuntingSettings settings;
  settings.max_time = 20.0;
  HuntingSamples held_samples, dying_samples;
  SampledSignal held(irregular(1.0), settings.max_time, held_samples);
  SampledSignal dying(irregular(0.985), settings.max_time, dying_samples);
  HuntingRun h, d;
  ASSERT_TRUE(follow_hunting(held, held_samples, settings, h));
  ASSERT_TRUE(follow_hunting(dying, dying_samples, settings, d));
  EXPECT_EQ(h.state, HuntingState::kIrregular) << hunting_state_name(h.state);
  EXPECT_NEAR(h.simulated_time, 6.0, 1e-9);
  EXPECT_TRUE(h.persists());
  EXPECT_EQ(d.state, HuntingState::kDecaying) << hunting_state_name(d.state);
  EXPECT_NEAR(d.simulated_time, settings.max_time, 1e-9);
  EXPECT_FALSE(d.persists());
}

}  // namespace
}  // namespace wrc
