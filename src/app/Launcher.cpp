// The `raytracer` command: blocks SIGINT and SIGTERM, then runs the program itself
// (libexec/raytracer, beside this file) in its place, same process, same arguments.
//
// Why: the program needs about 270 shared libraries (OpenImageIO, Mesa with LLVM, GLFW, ...),
// and the dynamic loader takes half a second (two under load) to load them before the
// program's first instruction runs; a Ctrl-C or SIGTERM in that time killed it unseen, with
// no message and status 130/143 from the shell. This launcher is linked statically: nothing is
// loaded before its first instruction, which blocks the two signals. A blocked signal stays
// pending through exec, and the program's InterruptWatch, made first thing in main, unblocks
// them once its handlers are set (app/Interrupt.h): an interrupt at any time is handled as
// documented. A signal that comes before this first instruction is one sent before the
// program exists, as for every program.
//
// Profiling or debugging the program itself: run libexec/raytracer directly (valgrind does
// not follow an exec without --trace-children=yes).
#include <cerrno>
#include <climits>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <unistd.h>

int main(int, char* argv[])
{
    sigset_t interrupts;
    sigemptyset(&interrupts);
    sigaddset(&interrupts, SIGINT);
    sigaddset(&interrupts, SIGTERM);
    sigprocmask(SIG_BLOCK, &interrupts, nullptr);

    static const char kProgram[] = "libexec/raytracer";
    char path[PATH_MAX + sizeof kProgram];
    const ssize_t length = readlink("/proc/self/exe", path, PATH_MAX);
    if (length <= 0) {
        std::fprintf(stderr, "raytracer: cannot find where the program is (/proc/self/exe): %s\n",
                     std::strerror(errno));
        return 1;
    }
    path[length] = '\0';
    char* folderEnd = std::strrchr(path, '/');
    std::strcpy(folderEnd != nullptr ? folderEnd + 1 : path, kProgram);
    execv(path, argv);
    std::fprintf(stderr, "raytracer: cannot start %s: %s\n", path, std::strerror(errno));
    return 1;
}
