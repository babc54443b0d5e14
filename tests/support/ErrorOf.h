#pragma once

// Test support: the message of the learnid::Error a call throws.

#include "model/Error.h"

#include <QString>

namespace learnid::test {

/// The message of the learnid::Error that f throws, or "<no error>".
template <typename F> QString errorOf(F &&f)
{
    try {
        f();
    } catch (const Error &e) {
        return e.message();
    }
    return QStringLiteral("<no error>");
}

} // namespace learnid::test
