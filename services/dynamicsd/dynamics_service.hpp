// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// wrc-dynamicsd's run management: START/STOP commands (RUN_COMMAND), live swaps
/// (CONTACT_SELECT), one simulation at a time (the lone wheelset's, or a vehicle's when the command
/// carries one of several bodies) advanced step by step from the service loop,
/// and what it publishes (WHEELSET_STATE: the samples of every output period in batches,
/// dynamicsd/state_batches.hpp; RUN_STATUS and INTEGRATOR_STATS
/// twice a second and on every change, RUN_SUMMARY at the end, repeated while idle so that a
/// client that lost it gets it). Messages that arrive while a step waits for a contact reply
/// only set flags here; they act at the next step boundary.

#include <lcm/lcm-cpp.hpp>

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "bus/service/heartbeat_monitor.hpp"
#include "bus/transport/channels.hpp"
#include "bus/transport/guarded_subscription.hpp"
#include "bus/transport/header_stamper.hpp"
#include "core/dynamics/simulation.hpp"
#include "core/dynamics/wheelset_simulation.hpp"
#include "core/vehicle_dynamics/vehicle_simulation.hpp"
#include "dynamicsd/bus_contact.hpp"
#include "dynamicsd/contact_clients.hpp"
#include "dynamicsd/state_batches.hpp"
#include "protocol/run/run_command_codec.hpp"
#include "protocol/run/run_output_codec.hpp"
#include "wrc/contact_select_t.hpp"
#include "wrc/run_command_t.hpp"
#include "wrc/run_summary_t.hpp"

namespace wrc::dynamics {

class DynamicsService {
 public:
  /// keepalive: called while a contact query waits for a (restarted) service (the heartbeat).
  /// lcm: opened at lcm_url (empty: the default bus), whose lanes carry the contact queries.
  /// instance: this process's instance name (a command naming another dynamics_instance is ignored).
  DynamicsService(lcm::LCM& lcm, const std::string& lcm_url, const bus::ChannelNames& names,
                  const std::string& instance, const std::string& sender, std::function<void()> keepalive = {});

  /// [-] most instances a summary names (run_summary_t::query_instances).
  static constexpr std::int32_t kMaxQueryInstances = 64;
  /// [s] a run over the bus starts no earlier than this after the service was created, so that
  /// its heartbeat monitor has heard every READY contact instance the run's queries are spread
  /// over (services beat every 0.5 s by default: two periods and a margin). A dynamics started for
  /// one run (wrc run, wrc sweep --bus) would otherwise send its first queries to the first
  /// instance it heard.
  static constexpr double kInstanceDiscovery = 1.2;
  /// Acts on pending commands and swaps, then advances a running simulation for up to
  /// budget seconds of wall time (whole steps) and publishes what is due.
  void poll(double budget);
  bool running() const { return simulation_ && simulation_->state() == RunState::kRunning; }
  /// What the service is doing, one line for its heartbeat (heartbeat_t::activity).
  std::string activity() const;
  /// The inboxes besides the bus that the service loop reads (the contact reply lanes).
  std::vector<bus::LaneSocket*> lanes() const { return clients_.reply_lanes(); }
  /// serving() false: run commands and swaps are ignored (this process is a duplicate of an older
  /// instance of the same name, bus/service/duplicate_instance_guard.hpp), as a duplicate contact
  /// service answers no queries. Default: always serving.
  void set_serving_check(std::function<bool()> serving) { serving_ = std::move(serving); }

 private:
  void on_command(const run_command_t& command);
  /// Whether command is a START over the bus that waits for the instances to be heard.
  bool discovering(const run_command_t& command) const;
  void on_select(const contact_select_t& select, std::uint64_t sender);
  void start(const run_command_t& command);
  /// The lone wheelset's simulation of request_, its states published by output period.
  std::unique_ptr<Simulation> make_wheelset_run(double nominal_radius);
  /// The vehicle's simulation of request_, every wheelset's states published by output period.
  /// @throws std::invalid_argument for scheduled swaps (a vehicle run takes none yet).
  std::unique_ptr<Simulation> make_vehicle_run(double nominal_radius);
  /// A FAILED run_status_t for command's request, with reason as its message.
  void publish_refusal(const run_command_t& command, const std::string& reason);
  void finish();
  std::shared_ptr<ContactEvaluator> make_contact(const std::string& model);
  /// Which instances answered the run's queries, and how many each, into summary.
  void add_query_instances(run_summary_t& summary) const;
  void apply_select();
  void publish_status(bool force);
  /// progress_t of the running run: fraction of simulated time done, wall time, time remaining.
  void publish_progress(double wall);
  template <class Message>
  void publish(const char* base, Message& message);

  lcm::LCM& lcm_;
  bus::ChannelNames names_;
  std::string instance_;
  double created_;  // [s] monotonic time the service was created
  std::function<void()> keepalive_;
  std::function<bool()> serving_;
  bus::HeaderStamper stamper_;
  bus::HeartbeatMonitor monitor_;
  ContactClients clients_;
  std::unique_ptr<bus::GuardedSubscription<run_command_t>> commands_;
  std::unique_ptr<bus::GuardedSubscription<contact_select_t>> selects_;

  std::optional<run_command_t> pending_command_;
  std::int64_t last_request_id_ = 0;
  std::optional<contact_select_t> pending_select_;
  /// Per sender (the verified nonce of its trailer): the last selection number acted on, and when
  /// (a count of selections), so that the longest silent sender goes first beyond kMaxSelectSenders.
  /// A sender republishes one choice with one number and numbers its later choices higher; one
  /// sender's numbers say nothing about another's, so a number far in the future (a garbled or
  /// hostile key holder) hides no one else's selections.
  struct SelectSender {
    std::int64_t seq = 0;
    std::int64_t heard = 0;
  };
  static constexpr std::size_t kMaxSelectSenders = 1024;
  std::map<std::uint64_t, SelectSender> select_senders_;
  std::int64_t selects_heard_ = 0;

  std::unique_ptr<Simulation> simulation_;
  WheelsetSimulation* wheelset_run_ = nullptr;  // simulation_ when it is the lone wheelset's
  VehicleSimulation* vehicle_run_ = nullptr;    // simulation_ when it is a vehicle's
  std::vector<std::shared_ptr<BusContact>> bus_contacts_;  // the run's contact over the bus (its start model and swaps)
  StateBatches states_;
  protocol::RunRequest request_;
  std::int64_t request_id_ = 0;
  std::shared_ptr<const WheelsetGeometry> geometry_;  // in-process runs
  double wall_start_ = 0;
  double wall_time_ = 0;
  double next_status_ = 0;
  std::string status_message_;
  std::optional<run_summary_t> summary_;
};

}  // namespace wrc::dynamics
