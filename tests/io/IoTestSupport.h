#pragma once

// Test support for the io tests: bit-exact comparisons (QCOMPARE on doubles is fuzzy) and the
// message of an expected learnid::Error.

#include "../support/ErrorOf.h"
#include "model/Error.h"

#include <Eigen/Core>
#include <QString>
#include <cstring>

namespace learnid::test {

inline bool bitEqual(double a, double b)
{
    return std::memcmp(&a, &b, sizeof a) == 0;
}

inline bool bitEqual(const Eigen::MatrixXd &a, const Eigen::MatrixXd &b)
{
    if (a.rows() != b.rows() || a.cols() != b.cols())
        return false;
    for (Eigen::Index i = 0; i < a.size(); ++i) {
        if (!bitEqual(a.data()[i], b.data()[i]))
            return false;
    }
    return true;
}

using learnid::test::errorOf;

} // namespace learnid::test

/// The message of the Error that the statement throws contains text.
#define LEARNID_VERIFY_ERROR(statement, text)                                                      \
    do {                                                                                           \
        const QString message_ = learnid::test::errorOf([&] { (void)(statement); });               \
        QVERIFY2(                                                                                  \
            message_.contains(text),                                                               \
            qPrintable(QStringLiteral("expected \"%1\" in: %2").arg(QString(text), message_)));    \
    } while (false)
