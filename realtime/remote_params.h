#pragma once
// remote.*: the plant of kind `remote`, a robot driven over the link of wire.h in real time
// (`cbbg drive`, or plant.kind=remote in a config). Known to every build.

#include <string>

#include "cbbg/framework/parameters.h"

namespace cbbg::realtime {

struct RemoteParams {
  std::string host = "127.0.0.1";  // where the robot listens
  long long port = 5005;
  std::string bind_host = "127.0.0.1";  // this end
  long long bind_port = 0;              // 0: one the system picks
  std::string key_file{};               // the shared key; empty: none
  long long timeout_periods = 10;       // a robot silent this long is lost
  double connect_timeout = 5.0;         // s

  // The hosts are IPv4 addresses (or localhost); throws std::invalid_argument naming the key.
  void validate() const;

  template <class Archive>
  void describe(Archive& a) {
    a.text("host", host, "the robot's IPv4 address (or localhost; the loopback by default)", {});
    a.integer("port", port, "the robot's UDP port", interval(1.0, 65535.0));
    a.text("bind_host", bind_host, "this controller's IPv4 address (or localhost)", {});
    a.integer("bind_port", bind_port, "this controller's UDP port; 0: one the system picks",
              interval(0.0, 65535.0));
    a.file("key_file", key_file,
           "a file holding the key shared with the robot (every datagram signed with it); "
           "empty: none");
    a.integer("timeout_periods", timeout_periods,
              "a robot silent for this many periods (trial.period) is lost: zero torque, stop",
              interval(1.0, 1000.0));
    a.number("connect_timeout", connect_timeout, "how long the handshake waits for the robot, s",
             interval(0.1, 600.0));
  }
};

}  // namespace cbbg::realtime
