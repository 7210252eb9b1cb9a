#include "cbbg/realtime/remote_params.h"

#include <stdexcept>
#include <string>
#include <utility>

#include "cbbg/realtime/udp_endpoint.h"

namespace cbbg::realtime {

void RemoteParams::validate() const {
  for (const auto& [key, value] :
       {std::pair{"remote.host", &host}, {"remote.bind_host", &bind_host}}) {
    if (!is_ipv4_host(*value)) {
      throw std::invalid_argument(std::string(key) +
                                  " must be an IPv4 address or localhost; got '" + *value + "'");
    }
  }
}

}  // namespace cbbg::realtime
