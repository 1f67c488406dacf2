#pragma once
/// @file
/// Checks a ContactQuery at the model boundary, before any computation.

#include "core/models/contact_model.hpp"

namespace wrc {

/// Smallest and largest FASTSIM element count accepted per direction (elements per strip and
/// strips) [-].
inline constexpr int kMinFastsimGrid = 2;
inline constexpr int kMaxFastsimGrid = 400;

/// Throws std::invalid_argument whose message names the field and its value when:
/// any pose value or rate is NaN or infinite; speed <= 0; a normal load is negative or not finite;
/// G <= 0; nu outside (0, 0.5); mu < 0 (or not finite); a FASTSIM count outside 2..400.
/// Loads are checked in both formulations (kElastic ignores them, but a NaN is still an error).
void validate_contact_query(const ContactQuery& query);

}  // namespace wrc
