// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// Reader for SIMPACK rail-wheel profile files (.prw wheel, .prr rail).

#include <string>

#include "core/profile/profile.hpp"
#include "core/profile/profile_file_options.hpp"

namespace wrc {

/// Reads a SIMPACK profile file.
///
/// Format: "key = value" lines inside header.begin/header.end and spline.begin/spline.end,
/// points (y z [weight]) between point.begin and point.end; '!' starts a comment (outside quotes),
/// so commented-out points are skipped. Used keys: header "type" (0 rail, 1 wheel; required),
/// "units.len.f" (file length unit per metre, e.g. 1000 for mm) or, if that is absent,
/// "units.len" ('mm', 'cm' or 'm'; default mm), "mirror.y", "mirror.z" (1 = negate the
/// coordinate), "comment". "inversion" only reverses the point order, which the reader handles
/// anyway (points may run in either lateral direction); shift, rotate and bound keys must be at
/// their neutral values (0 shift/rotation; bound min > max = no bound), else the file is rejected.
///
/// Orientation (as in the Manchester benchmark files): after mirroring, y runs towards the field
/// side and z points down. Wheel: s = y, F = z (a larger radius reaches further down). Rail:
/// u = y, v = -z.
///
/// Built-in cant rule (rails): options.built_in_cant if given; otherwise, if the "comment" value
/// contains "canted" (any case), the inclination written as "1:N" in the comment, or 1:40 (the
/// standard inclination, atan(1/40) rad) if no ratio is given, as for MBench_UIC60_v3.prr
/// ("already canted"); otherwise 0.
///
/// @param side the side the caller wants; a file of the other SIMPACK type is an error.
/// @throws ProfileError with file, line and reason for every malformed input.
ProfilePtr read_simpack_profile(const std::string& path, ProfileSide side,
                                const ProfileFileOptions& options = {});

}  // namespace wrc
