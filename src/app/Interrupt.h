#pragma once

namespace app {

// Ctrl-C (SIGINT) and SIGTERM: the first request is recorded so that the program can stop at
// its next safe point (a render between bands, a merge before it writes) and still end as
// documented; a second one ends the program at once. main() makes the one watch of the
// program as its first instruction. The launcher (app/Launcher.cpp) blocks both signals before
// it starts the program, so that one sent while the program's libraries load (half a second
// or more) waits, pending, until this watch is in place instead of killing the process
// unseen; the watch unblocks them once its handlers are set.
class InterruptWatch {
public:
    InterruptWatch();
    ~InterruptWatch();
    InterruptWatch(const InterruptWatch&) = delete;
    InterruptWatch& operator=(const InterruptWatch&) = delete;

    bool requested() const;
};

}  // namespace app
