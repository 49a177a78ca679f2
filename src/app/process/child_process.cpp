#include "app/process/child_process.h"

#include <cerrno>
#include <cstdlib>
#include <cstring>

#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include "shadelab/errors.h"

extern char** environ; // POSIX: the environment children inherit

namespace shadelab::app {

pid_t startChild(const std::vector<std::string>& args, const ChildStreams& streams, const std::string& who,
                 const std::string& hint) {
    std::vector<char*> argv, envp;
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    const std::string drop = streams.unsetVariable ? std::string(streams.unsetVariable) + "=" : "";
    for (char** e = environ; *e; ++e)
        if (drop.empty() || std::strncmp(*e, drop.c_str(), drop.size()) != 0) envp.push_back(*e);
    envp.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    if (streams.in >= 0) posix_spawn_file_actions_adddup2(&actions, streams.in, STDIN_FILENO);
    if (streams.out >= 0) posix_spawn_file_actions_adddup2(&actions, streams.out, STDOUT_FILENO);
    if (streams.errToOut) posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
    pid_t pid = 0;
    const int error = streams.searchPath
                          ? ::posix_spawnp(&pid, argv[0], &actions, nullptr, argv.data(), envp.data())
                          : ::posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), envp.data());
    posix_spawn_file_actions_destroy(&actions);
    if (error != 0)
        throw RuntimeError(who + ": cannot start " + args[0] + " (" + std::strerror(error) + ")" + hint);
    return pid;
}

int waitForChild(pid_t pid, const std::string& who, const std::string& what) {
    int status = 0;
    while (::waitpid(pid, &status, 0) < 0)
        if (errno != EINTR) {
            std::string message = who;
            message += ": waiting for " + what + ": ";
            message += std::strerror(errno);
            throw RuntimeError(message);
        }
    return status;
}

std::string childFailure(int status) {
    if (WIFEXITED(status))
        return WEXITSTATUS(status) == 0 ? "" : "exit status " + std::to_string(WEXITSTATUS(status));
    return "signal " + std::to_string(WTERMSIG(status));
}

bool onPath(const char* program) {
    const char* path = std::getenv("PATH");
    const std::string dirs = path ? path : "";
    std::size_t start = 0;
    while (start <= dirs.size()) {
        const std::size_t end = std::min(dirs.find(':', start), dirs.size());
        const std::string dir = end > start ? dirs.substr(start, end - start) : ".";
        if (::access((dir + "/" + program).c_str(), X_OK) == 0) return true;
        start = end + 1;
    }
    return false;
}

} // namespace shadelab::app
