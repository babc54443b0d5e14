#pragma once

#include <QString>
#include <stdexcept>

namespace learnid {

/// An error a user can act on: the message says what and where (file, key, joint, sample).
/// Thrown by planning, identification and file code; caught at the session and app boundary.
class Error : public std::runtime_error
{
public:
    explicit Error(const QString &message)
        : std::runtime_error(message.toStdString())
        , m_message(message)
    {}
    const QString &message() const { return m_message; }

private:
    QString m_message;
};

/// A message without its final full stop, to go on with it: "%1; nothing was stored".
/// Messages are whole sentences when they stand alone; a sentence ends once.
inline QString asClause(const QString &message)
{
    return message.endsWith(QLatin1Char('.')) ? message.chopped(1) : message;
}

} // namespace learnid
