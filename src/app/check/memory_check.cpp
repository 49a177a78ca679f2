#include "app/check/memory_check.h"

#include <cstdio>

#include <sys/resource.h>
#include <unistd.h>

#include "shadelab/errors.h"

namespace shadelab::app {

std::string mebibytes(double bytes) {
    char text[48];
    std::snprintf(text, sizeof text, "%.0f MiB", bytes / (1024.0 * 1024.0));
    return text;
}

void checkMemoryBudget(std::string_view what, double needBytes, std::string_view sizeField) {
    const long pages = ::sysconf(_SC_PHYS_PAGES), pageSize = ::sysconf(_SC_PAGESIZE);
    if (pages > 0 && pageSize > 0 && needBytes > double(pages) * double(pageSize))
        throw InputError(std::string(sizeField) + ": " + std::string(what) + " would need about " +
                         mebibytes(needBytes) + ", more than this machine's " +
                         mebibytes(double(pages) * double(pageSize)) + " of memory; choose a smaller size");
    rlimit limit{};
    if (::getrlimit(RLIMIT_AS, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY) return;
    if (needBytes > double(limit.rlim_cur))
        throw RuntimeError(std::string(what) + " needs about " + mebibytes(needBytes) +
                           " of address space, but the limit (ulimit -v) is " +
                           mebibytes(double(limit.rlim_cur)) +
                           "; raise it (ulimit -v unlimited) or choose a smaller --size or --subdivisions");
}

} // namespace shadelab::app
