// POSIX sockets and ppoll(2): a blocking socket, waited on with a timeout.

#include "cbbg/realtime/udp_endpoint.h"

#include <arpa/inet.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <charconv>
#include <stdexcept>
#include <system_error>

#include "cbbg/realtime/stop_request.h"
#include "cbbg/realtime/wire.h"

namespace cbbg::realtime {

bool is_ipv4_host(const std::string& host) {
  in_addr ignored{};
  return host == "localhost" || inet_pton(AF_INET, host.c_str(), &ignored) == 1;
}

Address address_of(std::string host, std::uint16_t port) {
  return {host == "localhost" ? "127.0.0.1" : std::move(host), port};
}

Address parse_address(std::string_view text, std::string_view what) {
  const auto refuse = [&] {
    return std::invalid_argument(std::string(what) +
                                 " must be HOST:PORT, HOST an IPv4 address or localhost and PORT "
                                 "0..65535 (e.g. 127.0.0.1:5005); got '" +
                                 std::string(text) + "'");
  };
  const std::size_t colon = text.rfind(':');
  if (colon == std::string_view::npos) throw refuse();
  const std::string host(text.substr(0, colon));
  if (!is_ipv4_host(host)) throw refuse();
  const std::string_view port = text.substr(colon + 1);
  unsigned value = 0;
  const auto [end, error] = std::from_chars(port.data(), port.data() + port.size(), value);
  if (port.empty() || error != std::errc() || end != port.data() + port.size() || value > 65535) {
    throw refuse();
  }
  return address_of(host, static_cast<std::uint16_t>(value));
}

Clock::duration to_duration(double seconds) {
  return std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(seconds));
}

std::uint64_t now_ns() {
  return static_cast<std::uint64_t>(
      std::chrono::duration_cast<std::chrono::nanoseconds>(Clock::now().time_since_epoch())
          .count());
}

sockaddr_in to_sockaddr(const Address& address) {
  sockaddr_in socket_address{};
  socket_address.sin_family = AF_INET;
  socket_address.sin_port = htons(address.port);
  inet_pton(AF_INET, address.host.c_str(), &socket_address.sin_addr);
  return socket_address;
}

bool same_peer(const sockaddr_in& a, const sockaddr_in& b) {
  return a.sin_addr.s_addr == b.sin_addr.s_addr && a.sin_port == b.sin_port;
}

UdpEndpoint::UdpEndpoint(const Address& local) {
  socket_ = ::socket(AF_INET, SOCK_DGRAM | SOCK_CLOEXEC, 0);
  if (socket_ < 0) throw std::system_error(errno, std::generic_category(), "a UDP socket");
  const sockaddr_in address = to_sockaddr(local);
  if (::bind(socket_, reinterpret_cast<const sockaddr*>(&address), sizeof address) != 0) {
    const int error = errno;
    ::close(socket_);
    throw std::system_error(error, std::generic_category(), "binding UDP " + local.text());
  }
  sockaddr_in bound{};
  socklen_t length = sizeof bound;
  ::getsockname(socket_, reinterpret_cast<sockaddr*>(&bound), &length);
  port_ = ntohs(bound.sin_port);
}

UdpEndpoint::~UdpEndpoint() { ::close(socket_); }

std::optional<UdpEndpoint::Received> UdpEndpoint::receive_until(Clock::time_point deadline) {
  while (!stop_requested()) {
    const long long left = std::max<long long>(
        std::chrono::duration_cast<std::chrono::nanoseconds>(deadline - Clock::now()).count(), 0);
    const timespec timeout{static_cast<time_t>(left / 1'000'000'000), left % 1'000'000'000};
    pollfd waiting{socket_, POLLIN, 0};
    const int ready = ::ppoll(&waiting, 1, &timeout, nullptr);
    if (ready > 0) {
      Received received;
      received.bytes.resize(kMaxDatagramBytes + 1);  // one more: a longer one is seen as such
      socklen_t length = sizeof received.from;
      const ssize_t size = ::recvfrom(socket_, received.bytes.data(), received.bytes.size(), 0,
                                      reinterpret_cast<sockaddr*>(&received.from), &length);
      if (size < 0) continue;  // an ICMP error of an earlier send, or EINTR
      received.bytes.resize(static_cast<std::size_t>(size));
      return received;
    }
    if (ready == 0 && Clock::now() >= deadline) return std::nullopt;
  }
  return std::nullopt;
}

void UdpEndpoint::send(const std::vector<std::uint8_t>& bytes, const sockaddr_in& to) {
  ::sendto(socket_, bytes.data(), bytes.size(), 0, reinterpret_cast<const sockaddr*>(&to),
           sizeof to);
}

}  // namespace cbbg::realtime
