#pragma once

// Shared by the fuzz targets (docs/fuzzing.md). A target feeds one input to the code under test;
// bad input must end in a learnid::Error or a refusal. Any other exception escapes and aborts
// the run, as do the crashes, undefined behaviour and leaks the sanitizers find. Properties a
// target checks beyond that (an accepted file writes and reads back unchanged) fail through
// fuzzFailure().

#include <QByteArray>
#include <QCoreApplication>
#include <QString>
#include <QtGlobal>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>

namespace learnid::fuzz {

/// The input as a QByteArray that does not copy it (and is not NUL terminated, as a file read
/// from disk is not guaranteed to be either).
inline QByteArray bytes(const uint8_t *data, size_t size)
{
    return QByteArray::fromRawData(reinterpret_cast<const char *>(data), qsizetype(size));
}

/// Reports a broken property and aborts, so that the fuzzer keeps the input as a crash.
[[noreturn]] inline void fuzzFailure(const char *what, const QString &detail = {})
{
    std::fprintf(stderr, "fuzz property violated: %s\n%s\n", what, qPrintable(detail));
    std::abort();
}

/// Qt's messages (warnings of the CAN units about every odd frame) only slow fuzzing down.
inline void quietMessages()
{
    static const bool installed = [] {
        qInstallMessageHandler([](QtMsgType, const QMessageLogContext &, const QString &) {});
        return true;
    }();
    Q_UNUSED(installed)
}

/// The application object the CAN units need for their timers and queued calls; made once and
/// kept for the whole run (the pointer keeps it reachable for the leak checker).
inline QCoreApplication *application()
{
    static int argc = 1;
    static char name[] = "learnid-fuzz";
    static char *argv[] = {name, nullptr};
    static QCoreApplication *app = [] {
        quietMessages();
        return new QCoreApplication(argc, argv);
    }();
    return app;
}

/// Reads the input from the front: bytes run out as zeros, never past the end.
class InputReader
{
public:
    InputReader(const uint8_t *data, size_t size)
        : m_data(data)
        , m_size(size)
    {}
    bool atEnd() const { return m_pos >= m_size; }
    uint8_t byte() { return atEnd() ? 0 : m_data[m_pos++]; }
    /// Up to n bytes (fewer at the end).
    QByteArray take(size_t n)
    {
        const size_t k = qMin(n, m_size - qMin(m_pos, m_size));
        const QByteArray b(reinterpret_cast<const char *>(m_data + m_pos), qsizetype(k));
        m_pos += k;
        return b;
    }

private:
    const uint8_t *m_data;
    size_t m_size;
    size_t m_pos = 0;
};

} // namespace learnid::fuzz
