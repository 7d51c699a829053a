#include "app/Interrupt.h"

#include <csignal>
#include <unistd.h>

namespace app {

namespace {

// Signal handlers can only share a lock-free flag with the program.
volatile std::sig_atomic_t interruptRequested = 0;

extern "C" void onInterrupt(int signal)
{
    if (interruptRequested) {
        std::signal(signal, SIG_DFL);
        std::raise(signal);
        return;
    }
    interruptRequested = 1;
}

}  // namespace

InterruptWatch::InterruptWatch()
{
    interruptRequested = 0;
    std::signal(SIGINT, onInterrupt);
    std::signal(SIGTERM, onInterrupt);
    // Blocked by the launcher (or by a parent: a mask is inherited through exec), they would
    // never arrive; one sent before now, pending, is delivered here, to the handler.
    sigset_t signals;
    sigemptyset(&signals);
    sigaddset(&signals, SIGINT);
    sigaddset(&signals, SIGTERM);
    sigprocmask(SIG_UNBLOCK, &signals, nullptr);
}

InterruptWatch::~InterruptWatch()
{
    std::signal(SIGINT, SIG_DFL);
    std::signal(SIGTERM, SIG_DFL);
}

bool InterruptWatch::requested() const
{
    return interruptRequested != 0;
}

}  // namespace app
