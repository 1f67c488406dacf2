#pragma once
/// @file
/// Checks a ContactQuery at the model boundary, before any computation.

#include "core/model_interface/contact_model.hpp"

namespace wrc {

// The limits below are the one source of these rules: the bus adapter (services/contactd) checks
// its message fields against the same constants, so a query is accepted or rejected alike in-process
// and over the bus.

/// Smallest and largest FASTSIM element count accepted per direction (elements per strip and
/// strips) [-], both included.
inline constexpr int kMinFastsimGrid = 2;
inline constexpr int kMaxFastsimGrid = 400;

/// Shear modulus G: positive, at most this [Pa] (steel is 8.2e10; 1e13 leaves any real material in).
inline constexpr double kMaxShearModulus = 1e13;
/// Poisson's ratio nu: strictly between these [-] (0.5 is incompressible: Kalker's coefficients and
/// the contact modulus degenerate; 0 is no material either).
inline constexpr double kMinPoissonRatio = 0.0;
inline constexpr double kMaxPoissonRatio = 0.5;
/// Friction coefficient mu: from 0 up to this, both included [-].
inline constexpr double kMaxFriction = 10.0;
/// Rolling speed: positive, at most this [m/s].
inline constexpr double kMaxSpeed = 1000.0;

/// Throws std::invalid_argument whose message names the field and its value when:
/// any pose value or rate is NaN or infinite; speed not in (0, kMaxSpeed]; a normal load is
/// negative or not finite; G not in (0, kMaxShearModulus]; nu not in (kMinPoissonRatio,
/// kMaxPoissonRatio); mu not in [0, kMaxFriction]; a FASTSIM count outside
/// kMinFastsimGrid..kMaxFastsimGrid. Loads are checked in both formulations (kElastic ignores them,
/// but a NaN is still an error).
void validate_contact_query(const ContactQuery& query);

}  // namespace wrc
