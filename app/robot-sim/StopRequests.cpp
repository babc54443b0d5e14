#include "robot-sim/StopRequests.h"

#include <QCoreApplication>
#include <csignal>
#include <sys/socket.h>
#include <sys/stat.h>
#include <unistd.h>

namespace learnid::robotsim {

namespace {

int g_signalFds[2] = {-1, -1};

extern "C" void onStopSignal(int signal)
{
    const char byte = char(signal);
    [[maybe_unused]] const ssize_t n = ::write(g_signalFds[0], &byte, 1);
}

bool stdinIsPipeOrSocket()
{
    struct stat st;
    return ::fstat(STDIN_FILENO, &st) == 0 && (S_ISFIFO(st.st_mode) || S_ISSOCK(st.st_mode));
}

} // namespace

StopRequests::StopRequests(QObject *parent)
    : QObject(parent)
{
    if (::socketpair(AF_UNIX, SOCK_STREAM, 0, g_signalFds) == 0) {
        m_signalNotifier = std::make_unique<QSocketNotifier>(g_signalFds[1], QSocketNotifier::Read);
        connect(m_signalNotifier.get(), &QSocketNotifier::activated, this,
                &StopRequests::readSignal);
        struct sigaction action = {};
        action.sa_handler = onStopSignal;
        sigemptyset(&action.sa_mask);
        action.sa_flags = SA_RESTART;
        ::sigaction(SIGINT, &action, nullptr);
        ::sigaction(SIGTERM, &action, nullptr);
    }
    if (stdinIsPipeOrSocket()) {
        m_stdinNotifier = std::make_unique<QSocketNotifier>(STDIN_FILENO, QSocketNotifier::Read);
        connect(m_stdinNotifier.get(), &QSocketNotifier::activated, this, &StopRequests::readStdin);
    }
}

StopRequests::~StopRequests()
{
    ::signal(SIGINT, SIG_DFL);
    ::signal(SIGTERM, SIG_DFL);
    m_signalNotifier.reset();
    for (int &fd : g_signalFds) {
        if (fd >= 0)
            ::close(fd);
        fd = -1;
    }
}

void StopRequests::readSignal()
{
    char byte = 0;
    if (::read(g_signalFds[1], &byte, 1) != 1)
        return;
    emit stopRequested(byte == SIGINT
                           ? QCoreApplication::translate("learnid-robot-sim", "SIGINT")
                           : QCoreApplication::translate("learnid-robot-sim", "SIGTERM"));
}

void StopRequests::readStdin()
{
    char buffer[256];
    const ssize_t n = ::read(STDIN_FILENO, buffer, sizeof buffer);
    if (n > 0) {
        m_stdinBuffer.append(buffer, n);
        for (qsizetype end = m_stdinBuffer.indexOf('\n'); end >= 0;
             end = m_stdinBuffer.indexOf('\n')) {
            const QString line = QString::fromUtf8(m_stdinBuffer.left(end)).trimmed();
            m_stdinBuffer.remove(0, end + 1);
            if (!line.isEmpty())
                emit lineReceived(line);
        }
        return;
    }
    m_stdinNotifier->setEnabled(false);
    emit stopRequested(QCoreApplication::translate("learnid-robot-sim", "stdin closed"));
}

} // namespace learnid::robotsim
