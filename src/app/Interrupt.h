#pragma once

namespace app {

// Ctrl-C (SIGINT) and SIGTERM during a render: the first request is recorded so the render
// can stop between bands and still write what it has; a second one ends the program at once.
class InterruptWatch {
public:
    InterruptWatch();
    ~InterruptWatch();
    InterruptWatch(const InterruptWatch&) = delete;
    InterruptWatch& operator=(const InterruptWatch&) = delete;

    bool requested() const;
};

}  // namespace app
