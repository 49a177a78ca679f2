// Starting a program as a child and waiting for it, the one way shadelab does it (`report` runs gnuplot,
// `bench` times `shadelab render`): posix_spawn with an argument vector — never a shell, so nothing taken
// from a file name or a scene is read as code — standard streams given as file descriptors, and EINTR
// retried.
#pragma once

#include <string>
#include <vector>

#include <sys/types.h>

namespace shadelab::app {

struct ChildStreams {
    int in = -1;                         // the child's standard input, or −1: the parent's
    int out = -1;                        // its standard output, or −1: the parent's
    bool errToOut = false;               // its standard error joins its standard output
    const char* unsetVariable = nullptr; // the parent's environment without this variable
    bool searchPath = false;             // args[0] found on PATH (posix_spawnp), else a path
};

// Starts `args`. Throws RuntimeError "<who>: cannot start <args[0]> (<reason>)<hint>" if it cannot.
pid_t startChild(const std::vector<std::string>& args, const ChildStreams& streams, const std::string& who,
                 const std::string& hint = "");
// Waits for `pid` and returns its wait status. Throws RuntimeError naming `who` and `what` if waiting fails.
int waitForChild(pid_t pid, const std::string& who, const std::string& what);
// "exit status N" or "signal N"; "" for a clean exit (status 0).
std::string childFailure(int status);
// Whether `program` is an executable file in a folder of PATH.
bool onPath(const char* program);

} // namespace shadelab::app
