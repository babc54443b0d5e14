#include "can/TcpLowLatency.h"

#include <QtGlobal>

#ifdef Q_OS_LINUX
#include <cstdlib>
#include <dirent.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <sys/socket.h>
#endif

namespace learnid {

int setNoDelayOnAllTcpSockets()
{
    int set = 0;
#ifdef Q_OS_LINUX
    DIR *fds = opendir("/proc/self/fd");
    if (!fds)
        return 0;
    const int own = dirfd(fds);
    while (const dirent *entry = readdir(fds)) {
        char *end = nullptr;
        const long fd = std::strtol(entry->d_name, &end, 10);
        if (end == entry->d_name || *end != '\0' || fd == own)
            continue;
        int type = 0;
        socklen_t length = sizeof(type);
        if (getsockopt(int(fd), SOL_SOCKET, SO_TYPE, &type, &length) != 0 || type != SOCK_STREAM)
            continue; // not a socket, or not a stream
        sockaddr_storage address{};
        length = sizeof(address);
        if (getsockname(int(fd), reinterpret_cast<sockaddr *>(&address), &length) != 0 ||
            (address.ss_family != AF_INET && address.ss_family != AF_INET6))
            continue; // a Unix socket
        const int one = 1;
        if (setsockopt(int(fd), IPPROTO_TCP, TCP_NODELAY, &one, sizeof(one)) == 0)
            ++set;
    }
    closedir(fds);
#endif
    return set;
}

} // namespace learnid
