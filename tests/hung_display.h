// An X display that takes connections and never answers (a hung X server, another program
// on its port): a listener on 127.0.0.1:6000+N, which is display N over TCP, for the first
// free N in 200-399. The kernel accepts connections into the listener's backlog and nobody
// answers them until release() closes the listener, which resets them.
#pragma once

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cstdint>
#include <string>

namespace skinsim::test {

class HungDisplay {
 public:
  HungDisplay() {
    listener_ = socket(AF_INET, SOCK_STREAM, 0);
    if (listener_ < 0) return;
    for (int n = 200; n < 400; ++n) {
      sockaddr_in address{};
      address.sin_family = AF_INET;
      address.sin_port = htons(static_cast<std::uint16_t>(6000 + n));
      address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
      if (bind(listener_, reinterpret_cast<sockaddr*>(&address), sizeof address) == 0) {
        if (listen(listener_, 4) == 0) name_ = "127.0.0.1:" + std::to_string(n);
        return;
      }
    }
  }
  ~HungDisplay() { release(); }
  HungDisplay(const HungDisplay&) = delete;
  HungDisplay& operator=(const HungDisplay&) = delete;

  // The DISPLAY value, or "" when no listener could be set up.
  const std::string& name() const { return name_; }
  void release() {
    if (listener_ >= 0) close(listener_);
    listener_ = -1;
  }

 private:
  int listener_ = -1;
  std::string name_;
};

}  // namespace skinsim::test
