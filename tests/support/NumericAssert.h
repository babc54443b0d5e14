#pragma once

// Test support: tolerance assertions for scalars and Eigen matrices that print the values
// (QCOMPARE's fuzzy compare has a fixed relative tolerance, and says nothing about its scale).

#include <Eigen/Core>
#include <QString>
#include <QTest>
#include <cmath>

namespace learnid::test {

inline QString formatNumber(double v)
{
    return QString::number(v, 'g', 17);
}

/// max |a - b| over all entries; +inf when the shapes differ or an entry is not finite.
inline double maxAbsDifference(const Eigen::MatrixXd &a, const Eigen::MatrixXd &b)
{
    if (a.rows() != b.rows() || a.cols() != b.cols())
        return INFINITY;
    const double d = (a - b).cwiseAbs().maxCoeff();
    return std::isfinite(d) ? d : INFINITY;
}

} // namespace learnid::test

/// |actual - expected| <= tolerance (fails on NaN).
#define LEARNID_COMPARE_NEAR(actual, expected, tolerance)                                          \
    do {                                                                                           \
        const double actual_ = (actual);                                                           \
        const double expected_ = (expected);                                                       \
        const double tolerance_ = (tolerance);                                                     \
        QVERIFY2(                                                                                  \
            std::abs(actual_ - expected_) <= tolerance_,                                           \
            qPrintable(QStringLiteral("%1 = %2, expected %3 +- %4 (difference %5)")                \
                           .arg(QStringLiteral(#actual), learnid::test::formatNumber(actual_),     \
                                learnid::test::formatNumber(expected_),                            \
                                learnid::test::formatNumber(tolerance_),                           \
                                learnid::test::formatNumber(actual_ - expected_))));               \
    } while (0)

/// max |actual - expected| <= tolerance over all entries (fails on shape mismatch or NaN).
#define LEARNID_COMPARE_MATRIX(actual, expected, tolerance)                                        \
    do {                                                                                           \
        const Eigen::MatrixXd actual_ = (actual);                                                  \
        const Eigen::MatrixXd expected_ = (expected);                                              \
        const double tolerance_ = (tolerance);                                                     \
        const double diff_ = learnid::test::maxAbsDifference(actual_, expected_);                  \
        QVERIFY2(diff_ <= tolerance_,                                                              \
                 qPrintable(QStringLiteral("%1: max difference %2 > %3 (%4x%5 vs %6x%7)")          \
                                .arg(QStringLiteral(#actual), learnid::test::formatNumber(diff_),  \
                                     learnid::test::formatNumber(tolerance_))                      \
                                .arg(actual_.rows())                                               \
                                .arg(actual_.cols())                                               \
                                .arg(expected_.rows())                                             \
                                .arg(expected_.cols())));                                          \
    } while (0)
