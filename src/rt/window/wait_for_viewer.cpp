#include <array>

#include "rt/window/picture_window.h"

#include <poll.h>
#include <unistd.h>

namespace rt {

void wait_for_enter_or_close(const PictureWindow& window, int fd,
                             const std::function<bool()>& stop) {
    constexpr int kPollMilliseconds = 50;  // how soon a closed window or Ctrl-C is noticed
    while (!window.closed() && !window.lost() && !(stop && stop())) {
        pollfd input{fd, POLLIN, 0};
        if (::poll(&input, 1, kPollMilliseconds) <= 0) {
            continue;  // timeout, or a signal (checked above)
        }
        std::array<char, 256> bytes{};
        const ssize_t n = ::read(fd, bytes.data(), bytes.size());
        if (n <= 0) {
            return;  // end of input: no one will press Enter
        }
        for (ssize_t i = 0; i < n; ++i) {
            if (bytes[static_cast<std::size_t>(i)] == '\n') {
                return;
            }
        }
    }
}

}  // namespace rt
