// SPDX-License-Identifier: Apache-2.0
#include "bus/transport/lane_socket.hpp"

#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

#include "bus/transport/drop_counters.hpp"
#include "bus/transport/guarded_subscription.hpp"

namespace wrc::bus {
namespace {

// LCM's UDP multicast protocol: a datagram starts with a big-endian magic number and the sender's
// message sequence number. A short message ("LC02") follows with the channel name, NUL-terminated,
// and the payload; a fragment of a longer message ("LC03") with the message's payload size, the
// fragment's offset into it, the fragment's number and the number of fragments, and, in fragment 0
// only, the channel name before its part of the payload.
constexpr std::uint32_t kMagicShort = 0x4c433032;  // "LC02"
constexpr std::uint32_t kMagicLong = 0x4c433033;   // "LC03"
constexpr std::size_t kShortHeader = 8;            // [B] magic, sequence
constexpr std::size_t kLongHeader = 20;            // [B] magic, sequence, size, offset, number, count
constexpr std::size_t kMaxChannel = 63;            // [B] LCM_MAX_CHANNEL_NAME_LENGTH
constexpr std::size_t kMaxDatagram = 65536;        // [B] the largest UDP payload
constexpr std::size_t kMaxPartials = 8;            // [-] fragmented messages put together at once

std::uint32_t be32(const std::uint8_t* p) {
  return (std::uint32_t{p[0]} << 24) | (std::uint32_t{p[1]} << 16) | (std::uint32_t{p[2]} << 8) | p[3];
}
std::uint16_t be16(const std::uint8_t* p) { return static_cast<std::uint16_t>((p[0] << 8) | p[1]); }

struct ParsedUrl {
  in_addr group{};
  int port = 0;
  long recv_buf_size = 0;  // [B] 0: the kernel's default
};

ParsedUrl parse_udpm_url(const std::string& url) {
  const std::string scheme = "udpm://";
  if (url.rfind(scheme, 0) != 0) throw std::invalid_argument("lane URL '" + url + "' is not a udpm:// URL");
  const std::size_t options = std::min(url.find('?'), url.size());
  const std::size_t colon = url.find(':', scheme.size());
  if (colon == std::string::npos || colon > options)
    throw std::invalid_argument("lane URL '" + url + "' names no port");
  ParsedUrl parsed;
  const std::string host = url.substr(scheme.size(), colon - scheme.size());
  if (inet_pton(AF_INET, host.c_str(), &parsed.group) != 1 || !IN_MULTICAST(ntohl(parsed.group.s_addr)))
    throw std::invalid_argument("lane URL '" + url + "': '" + host + "' is not an IPv4 multicast group");
  const auto number = [&url](const std::string& text, long lo, long hi, const char* what) {
    std::size_t used = 0;
    long value = 0;
    try {
      value = std::stol(text, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (text.empty() || used != text.size() || value < lo || value > hi)
      throw std::invalid_argument("lane URL '" + url + "': " + what + " '" + text + "' is not a number from " +
                                  std::to_string(lo) + " to " + std::to_string(hi));
    return value;
  };
  parsed.port = static_cast<int>(number(url.substr(colon + 1, options - colon - 1), 1, 65535, "port"));
  for (std::size_t at = options + 1; at < url.size();) {
    const std::size_t end = std::min(url.find('&', at), url.size());
    const std::string option = url.substr(at, end - at);
    const std::string key = "recv_buf_size=";
    if (option.rfind(key, 0) == 0)
      parsed.recv_buf_size = number(option.substr(key.size()), 1, 1L << 30, "recv_buf_size");
    at = end + 1;
  }
  return parsed;
}

std::runtime_error system_error(const std::string& what, const std::string& url) {
  return std::runtime_error(what + " for lane '" + url + "' failed: " + std::strerror(errno));
}

}  // namespace

LaneSocket::LaneSocket(const std::string& url) : url_(url), buffer_(kMaxDatagram) {
  const ParsedUrl parsed = parse_udpm_url(url);
  fd_ = ::socket(AF_INET, SOCK_DGRAM | SOCK_CLOEXEC | SOCK_NONBLOCK, 0);
  if (fd_ < 0) throw system_error("socket()", url);
  try {
    const int on = 1;
    if (::setsockopt(fd_, SOL_SOCKET, SO_REUSEADDR, &on, sizeof on) != 0) throw system_error("SO_REUSEADDR", url);
    if (::setsockopt(fd_, SOL_SOCKET, SO_TIMESTAMP, &on, sizeof on) != 0) throw system_error("SO_TIMESTAMP", url);
    if (parsed.recv_buf_size > 0) {
      const int size = static_cast<int>(parsed.recv_buf_size);
      if (::setsockopt(fd_, SOL_SOCKET, SO_RCVBUF, &size, sizeof size) != 0) throw system_error("SO_RCVBUF", url);
    }
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_addr.s_addr = htonl(INADDR_ANY);
    address.sin_port = htons(static_cast<std::uint16_t>(parsed.port));
    if (::bind(fd_, reinterpret_cast<const sockaddr*>(&address), sizeof address) != 0) throw system_error("bind()", url);
    ip_mreq membership{};
    membership.imr_multiaddr = parsed.group;
    membership.imr_interface.s_addr = htonl(INADDR_ANY);
    if (::setsockopt(fd_, IPPROTO_IP, IP_ADD_MEMBERSHIP, &membership, sizeof membership) != 0)
      throw system_error("joining the multicast group (is there a multicast route? see `ip route`)", url);
  } catch (...) {
    ::close(fd_);
    throw;
  }
}

LaneSocket::~LaneSocket() { ::close(fd_); }

void LaneSocket::subscribe(const std::string& channel, RawHandler handler) {
  if (!handlers_.emplace(channel, std::move(handler)).second)
    throw std::invalid_argument("lane '" + url_ + "' has a subscriber to '" + channel + "' already");
}

void LaneSocket::unsubscribe(const std::string& channel) { handlers_.erase(channel); }

int LaneSocket::handle_timeout(int timeout_ms) {
  sockaddr_in from{};
  iovec part{buffer_.data(), buffer_.size()};
  alignas(cmsghdr) char control[CMSG_SPACE(sizeof(timeval))];
  msghdr header{};
  header.msg_name = &from;
  header.msg_namelen = sizeof from;
  header.msg_iov = &part;
  header.msg_iovlen = 1;
  header.msg_control = control;
  header.msg_controllen = sizeof control;
  ssize_t size = ::recvmsg(fd_, &header, MSG_DONTWAIT);
  if (size < 0 && (errno == EAGAIN || errno == EWOULDBLOCK) && timeout_ms != 0) {
    pollfd wait{fd_, POLLIN, 0};
    const int ready = ::poll(&wait, 1, timeout_ms);
    if (ready <= 0) return ready;
    header.msg_namelen = sizeof from;
    header.msg_controllen = sizeof control;
    size = ::recvmsg(fd_, &header, MSG_DONTWAIT);
  }
  if (size < 0) return (errno == EAGAIN || errno == EWOULDBLOCK) ? 0 : -1;
  ++counters_.datagrams;
  std::int64_t utime = 0;
  for (cmsghdr* c = CMSG_FIRSTHDR(&header); c != nullptr; c = CMSG_NXTHDR(&header, c)) {
    if (c->cmsg_level != SOL_SOCKET || c->cmsg_type != SCM_TIMESTAMP) continue;
    timeval stamp{};
    std::memcpy(&stamp, CMSG_DATA(c), sizeof stamp);
    utime = static_cast<std::int64_t>(stamp.tv_sec) * 1000000 + stamp.tv_usec;
  }
  const std::uint64_t sender = (std::uint64_t{ntohl(from.sin_addr.s_addr)} << 16) | ntohs(from.sin_port);
  on_datagram(buffer_.data(), static_cast<std::size_t>(size), sender, utime);
  return 1;
}

void LaneSocket::on_datagram(const std::uint8_t* bytes, std::size_t size, std::uint64_t sender, std::int64_t utime) {
  if (size < kShortHeader) return malformed(std::to_string(size) + " bytes, shorter than LCM's header");
  const std::uint32_t magic = be32(bytes);
  if (magic == kMagicLong) return on_fragment(bytes, size, sender, utime);
  if (magic != kMagicShort) return malformed("not an LCM datagram (magic number " + std::to_string(magic) + ")");
  const auto* name = reinterpret_cast<const char*>(bytes + kShortHeader);
  const std::size_t length = ::strnlen(name, std::min(size - kShortHeader, kMaxChannel + 1));
  if (length > kMaxChannel || kShortHeader + length >= size)
    return malformed("an LCM datagram whose channel name is not NUL-terminated within 63 characters");
  const std::size_t offset = kShortHeader + length + 1;
  deliver(std::string(name, length), bytes + offset, size - offset, utime);
}

void LaneSocket::on_fragment(const std::uint8_t* bytes, std::size_t size, std::uint64_t sender, std::int64_t utime) {
  if (size < kLongHeader) return malformed(std::to_string(size) + " bytes, shorter than LCM's fragment header");
  const std::uint32_t sequence = be32(bytes + 4);
  const std::uint32_t total = be32(bytes + 8);
  const std::uint32_t offset = be32(bytes + 12);
  const std::uint16_t number = be16(bytes + 16);
  const std::uint16_t count = be16(bytes + 18);
  if (total > kDefaultMaxMessageBytes)
    return malformed("a fragmented message of " + std::to_string(total) + " bytes, more than the " +
                     std::to_string(kDefaultMaxMessageBytes) + " accepted");
  if (count == 0 || number >= count) return malformed("fragment " + std::to_string(number) + " of " + std::to_string(count));
  std::size_t start = kLongHeader;
  std::string channel;
  if (number == 0) {
    const auto* name = reinterpret_cast<const char*>(bytes + start);
    const std::size_t length = ::strnlen(name, std::min(size - start, kMaxChannel + 1));
    if (length > kMaxChannel || start + length >= size)
      return malformed("a first fragment whose channel name is not NUL-terminated within 63 characters");
    channel.assign(name, length);
    start += length + 1;
  }
  const std::size_t part = size - start;
  if (std::size_t{offset} + part > total)
    return malformed("a fragment reaching byte " + std::to_string(std::size_t{offset} + part) + " of a " +
                     std::to_string(total) + "-byte message");
  auto it = partials_.begin();
  while (it != partials_.end() && !(it->sender == sender && it->sequence == sequence)) ++it;
  if (it != partials_.end() && (it->data.size() != total || it->arrived.size() != count)) {
    partials_.erase(it);  // the sender started another message under the same number
    it = partials_.end();
  }
  if (it == partials_.end()) {
    if (partials_.size() == kMaxPartials) {
      partials_.pop_front();
      ++counters_.abandoned;
    }
    partials_.push_back(Partial{sender, sequence, {}, std::vector<std::uint8_t>(total), std::vector<bool>(count), count,
                                utime});
    it = std::prev(partials_.end());
  }
  if (it->arrived[number]) return;  // a copy of a fragment read before
  it->arrived[number] = true;
  --it->missing;
  if (number == 0) it->channel = std::move(channel);
  std::memcpy(it->data.data() + offset, bytes + start, part);
  if (it->missing > 0) return;
  const Partial whole = std::move(*it);
  partials_.erase(it);
  deliver(whole.channel, whole.data.data(), whole.data.size(), whole.first_utime);
}

void LaneSocket::deliver(const std::string& channel, const std::uint8_t* data, std::size_t size, std::int64_t utime) {
  const auto found = handlers_.find(channel);
  if (found == handlers_.end()) {
    ++counters_.unsubscribed;
    return;
  }
  ++counters_.messages;
  lcm::ReceiveBuffer message{};
  message.data = const_cast<std::uint8_t*>(data);  // lcm::ReceiveBuffer's field is not const
  message.data_size = static_cast<std::uint32_t>(size);
  message.recv_utime = utime;
  found->second(message, channel);
}

void LaneSocket::malformed(const std::string& why) {
  ++counters_.malformed;
  record_drop(DropKind::kUndecodable, "lane " + url_, "(no channel)", why);
}

}  // namespace wrc::bus
