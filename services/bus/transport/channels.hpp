// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// Channel names of the wrc bus and the optional prefix that lets several simulations share one
/// bus (`--channel-prefix SIM1` turns HEARTBEAT into SIM1.HEARTBEAT).

#include <string>

namespace wrc::bus {

/// Base names of every channel of the product (before the prefix). Per-model and per-client
/// channels append ".<model>" or ".<client id>".
namespace channel {
inline constexpr const char* kHeartbeat = "HEARTBEAT";              ///< heartbeat_t, every service
inline constexpr const char* kPing = "PING";                        ///< ping_request_t to wrc-pingd
inline constexpr const char* kPingReply = "PING_REPLY";             ///< ping_reply_t, + ".<client>"
inline constexpr const char* kContactQuery = "CONTACT_QUERY";       ///< contact_query_t, + ".<model>"
inline constexpr const char* kContactReply = "CONTACT_REPLY";       ///< contact_reply_t, + ".<client>"
inline constexpr const char* kContactSelect = "CONTACT_SELECT";     ///< contact_select_t (hot swap)
inline constexpr const char* kGeometryRequest = "GEOMETRY_REQUEST"; ///< geometry_request_t
inline constexpr const char* kGeometryTable = "GEOMETRY_TABLE";     ///< geometry_table_t
inline constexpr const char* kSplineModel = "SPLINE_MODEL";         ///< spline_model_t
inline constexpr const char* kModelPieceRequest = "MODEL_PIECE_REQUEST";  ///< model_piece_request_t
inline constexpr const char* kModelPiece = "MODEL_PIECE";           ///< model_piece_t
inline constexpr const char* kProgress = "PROGRESS";                ///< progress_t
inline constexpr const char* kRunCommand = "RUN_COMMAND";           ///< run_command_t
inline constexpr const char* kRunStatus = "RUN_STATUS";             ///< run_status_t
inline constexpr const char* kWheelsetState = "WHEELSET_STATE";     ///< wheelset_states_t (batches of wheelset_state_t)
inline constexpr const char* kIntegratorStats = "INTEGRATOR_STATS"; ///< integrator_stats_t
inline constexpr const char* kRunSummary = "RUN_SUMMARY";           ///< run_summary_t
}  // namespace channel

/// LCM limits channel names to 63 characters.
inline constexpr std::size_t kMaxChannelLength = 63;

/// Maps base channel names to the names used on the bus, with the prefix applied.
class ChannelNames {
 public:
  /// prefix: empty, or letters, digits, '_' and '-' only (throws std::invalid_argument naming
  /// the bad prefix otherwise).
  explicit ChannelNames(std::string prefix = "");

  /// The prefix as given (may be empty).
  const std::string& prefix() const { return prefix_; }
  /// `<prefix>.<base>` or `<base>` without prefix; throws std::invalid_argument when the result
  /// is longer than kMaxChannelLength.
  std::string name(const std::string& base) const;
  /// `<prefix>.<base>.<suffix>`, e.g. name("CONTACT_QUERY", "onepoint").
  std::string name(const std::string& base, const std::string& suffix) const;

 private:
  std::string prefix_;
};

/// Escapes regular-expression characters: LCM treats a subscription's channel as a regex, and
/// '.' in "CONTACT_QUERY.onepoint" must only match itself.
std::string regex_escape(const std::string& channel);

}  // namespace wrc::bus
