// SPDX-License-Identifier: Apache-2.0
#pragma once
/// @file
/// A lane of the bus (bus/transport/lcm_url.hpp, lane_lcm_url) read in the caller's own thread.
/// LCM 1.3.1 reads each socket in a receive thread of its own and hands every message to the
/// caller's thread through a pipe: two thread hand-overs before a handler runs, each a sleeping
/// thread woken on a possibly halted core. A contact query or reply waits on both ends of every
/// round trip (docs/performance.md, "The cost of a query"), so the lanes that carry them are read
/// here from a socket of wrc's own: the kernel wakes the waiting thread itself.
///
/// The socket is what LCM's udpm provider opens (the lane's multicast group and port, address
/// reuse, the URL's recv_buf_size, kernel receive stamps) and the datagrams are LCM's (its UDP
/// multicast protocol: "LC02" short messages, "LC03" fragments of longer ones), so the senders
/// stay plain LCM objects and lcm-spy still reads a lane. A datagram in another format is dropped
/// and counted as undecodable (bus/transport/drop_counters.hpp); a channel nobody subscribed to is
/// read and ignored, as LCM does.

#include <lcm/lcm-cpp.hpp>

#include <cstdint>
#include <deque>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace wrc::bus {

/// Counters of one lane socket since it was opened.
struct LaneCounters {
  std::int64_t datagrams = 0;    ///< datagrams read
  std::int64_t messages = 0;     ///< whole messages handed to a subscriber
  std::int64_t unsubscribed = 0; ///< whole messages on channels nobody here reads
  std::int64_t malformed = 0;    ///< datagrams not in LCM's format, fragments that contradict their message
  std::int64_t abandoned = 0;    ///< fragmented messages given up incomplete (a fragment lost)
};

class LaneSocket {
 public:
  /// The handler of one channel: the whole message (data, size and LCM's receive time, as
  /// lcm::LCM hands it to a subscription) and the channel's name.
  using RawHandler = std::function<void(const lcm::ReceiveBuffer&, const std::string&)>;

  /// Opens the lane at url, a udpm URL ("udpm://GROUP:PORT?ttl=N&recv_buf_size=B", as
  /// lane_lcm_url gives it). Throws std::invalid_argument for a URL of another provider or one
  /// that does not parse, std::runtime_error naming the URL and the system's reason when the
  /// socket cannot be opened, bound or joined to the group.
  explicit LaneSocket(const std::string& url);
  ~LaneSocket();
  LaneSocket(const LaneSocket&) = delete;
  LaneSocket& operator=(const LaneSocket&) = delete;

  /// Hands the messages on channel (an exact name, no pattern) to handler, in this thread, from
  /// handle_timeout(). Throws std::invalid_argument when channel has a handler already.
  void subscribe(const std::string& channel, RawHandler handler);
  /// Stops handing channel's messages to anyone.
  void unsubscribe(const std::string& channel);

  /// The socket's descriptor, readable when a datagram waits (for poll()).
  int fileno() const { return fd_; }
  /// Waits up to timeout_ms [ms] (0: not at all, negative: without limit) for a datagram and reads
  /// it, handing it to its channel's handler when it completes a message. Returns 1 when a datagram
  /// was read, 0 when none came in time, -1 when reading failed (errno tells; EINTR after a signal).
  int handle_timeout(int timeout_ms);
  /// The lane's URL as given.
  const std::string& url() const { return url_; }
  /// Counters since the socket was opened.
  const LaneCounters& counters() const { return counters_; }

 private:
  /// A fragmented message being put together.
  struct Partial {
    std::uint64_t sender = 0;  // IPv4 address and port of the sending socket
    std::uint32_t sequence = 0;
    std::string channel;
    std::vector<std::uint8_t> data;
    std::vector<bool> arrived;  // per fragment
    int missing = 0;
    std::int64_t first_utime = 0;  // [us] receipt of the first fragment read
  };

  void on_datagram(const std::uint8_t* bytes, std::size_t size, std::uint64_t sender, std::int64_t utime);
  void on_fragment(const std::uint8_t* bytes, std::size_t size, std::uint64_t sender, std::int64_t utime);
  void deliver(const std::string& channel, const std::uint8_t* data, std::size_t size, std::int64_t utime);
  void malformed(const std::string& why);

  std::string url_;
  int fd_ = -1;
  std::vector<std::uint8_t> buffer_;  // one datagram
  std::map<std::string, RawHandler> handlers_;
  std::deque<Partial> partials_;  // oldest first
  LaneCounters counters_;
};

}  // namespace wrc::bus
