#pragma once
// One UDP socket, IPv4, with the two calls a real-time loop needs: send to an address, and
// wait for the next datagram until a deadline (or until a stop is asked: stop_request.h).

#include <netinet/in.h>

#include <chrono>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace cbbg::realtime {

using Clock = std::chrono::steady_clock;

// An IPv4 address and port: "127.0.0.1:5005", "localhost:5005" (the loopback address).
struct Address {
  std::string host = "127.0.0.1";
  std::uint16_t port = 0;
  std::string text() const { return host + ":" + std::to_string(port); }
};
// `host` (checked by is_ipv4_host) and `port` as an address, localhost as 127.0.0.1.
Address address_of(std::string host, std::uint16_t port);
// `text` as HOST:PORT, HOST a dotted IPv4 address or "localhost", PORT 0..65535. Throws
// std::invalid_argument naming `what` (a flag or key) and what is allowed.
Address parse_address(std::string_view text, std::string_view what);

// Whether `host` is a dotted IPv4 address or "localhost".
bool is_ipv4_host(const std::string& host);

// `seconds` as the clock's duration.
Clock::duration to_duration(double seconds);

// Nanoseconds on the steady clock: the stamps datagrams carry.
std::uint64_t now_ns();

class UdpEndpoint {
 public:
  // Bound to `local` (port 0: one the system picks). Throws std::system_error naming the
  // address when the system refuses it (in use, not this machine's).
  explicit UdpEndpoint(const Address& local);
  ~UdpEndpoint();
  UdpEndpoint(const UdpEndpoint&) = delete;
  UdpEndpoint& operator=(const UdpEndpoint&) = delete;

  std::uint16_t port() const { return port_; }

  struct Received {
    std::vector<std::uint8_t> bytes;
    sockaddr_in from{};
  };
  // The next datagram, or none when `deadline` passes or a stop is asked first.
  std::optional<Received> receive_until(Clock::time_point deadline);
  // Sends `bytes` to `to`; a full socket buffer or an unreachable peer loses the datagram, as
  // the network may (counted by the other side), and is not an error here.
  void send(const std::vector<std::uint8_t>& bytes, const sockaddr_in& to);

 private:
  int socket_ = -1;
  std::uint16_t port_ = 0;
};

sockaddr_in to_sockaddr(const Address& address);
bool same_peer(const sockaddr_in& a, const sockaddr_in& b);

}  // namespace cbbg::realtime
