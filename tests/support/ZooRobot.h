#pragma once
// Robot (a) of issue 23, the simulated real KUKA LWR4+ that the CAD model describes badly, built
// from the CAD URDF's text: every link's mass times a factor, its centre of mass moved, its
// inertia x1.4, the joint friction real arms show. One builder for tst_learnfromabort (fixed
// changes) and learnid-bench-zoo (changes drawn with a seed). Header-only: the tests' support
// files are.
#include <QRegularExpression>
#include <QString>
#include <QStringList>
#include <array>
#include <functional>

namespace learnid::support {

/// Joint Coulomb friction of robot (a) [N m]: joint 5's 0.93 N m is what the recorded logs of
/// ../shared/data/kuka-lwr4 show, where the CAD model says 0.2 (issue 23).
inline constexpr double kRobotACoulomb[7] = {0.94, 1.2, 0.6, 0.9, 0.93, 0.8, 0.3};

/// Every number of attribute `name` of `element` in `xml` replaced by f(i, value), i counting
/// the matches in document order.
inline QString replaceUrdfAttribute(const QString &xml, const QString &element, const QString &name,
                                    const std::function<QString(int, const QString &)> &f)
{
    const QRegularExpression re(
        QStringLiteral("(<%1\\b[^>]*\\b%2=\")([^\"]*)(\")").arg(element, name));
    QString out;
    qsizetype from = 0;
    int i = 0;
    for (auto it = re.globalMatch(xml); it.hasNext();) {
        const QRegularExpressionMatch m = it.next();
        out += xml.mid(from, m.capturedStart(2) - from);
        out += f(i++, m.captured(2));
        from = m.capturedEnd(2);
    }
    return out + xml.mid(from);
}

inline QString urdfNumber(double v)
{
    return QString::number(v, 'g', 12);
}

/// Robot (a) from the CAD URDF's text. The inertial blocks count in document order (the fixed
/// base's first): block i's mass times massFactor(i), then its centre of mass moved by
/// comOffset(i) [m] (all masses are asked first, then all offsets, so that a seeded draw is
/// reproducible); every inertia x1.4; Coulomb friction kRobotACoulomb, viscous the CAD's x1.5.
inline QString robotAUrdf(const QString &cad, const std::function<double(int)> &massFactor,
                          const std::function<std::array<double, 3>(int)> &comOffset)
{
    QString xml = replaceUrdfAttribute(
        cad, QStringLiteral("mass"), QStringLiteral("value"),
        [&](int i, const QString &v) { return urdfNumber(v.toDouble() * massFactor(i)); });
    for (const char *c : {"ixx", "iyy", "izz", "ixy", "ixz", "iyz"})
        xml = replaceUrdfAttribute(
            xml, QStringLiteral("inertia"), QString::fromLatin1(c),
            [](int, const QString &v) { return urdfNumber(v.toDouble() * 1.4); });
    // The <origin> inside each <inertial>.
    const QRegularExpression inertialOrigin(
        QStringLiteral("(<inertial>\\s*<mass[^>]*>\\s*<origin[^>]*xyz=\")([^\"]*)(\")"));
    QString moved;
    qsizetype from = 0;
    int i = 0;
    for (auto it = inertialOrigin.globalMatch(xml); it.hasNext(); ++i) {
        const QRegularExpressionMatch m = it.next();
        QStringList xyz = m.captured(2).split(QLatin1Char(' '), Qt::SkipEmptyParts);
        const std::array<double, 3> d = comOffset(i);
        for (int k = 0; k < 3 && k < xyz.size(); ++k)
            xyz[k] = urdfNumber(xyz[k].toDouble() + d[size_t(k)]);
        moved += xml.mid(from, m.capturedStart(2) - from) + xyz.join(QLatin1Char(' '));
        from = m.capturedEnd(2);
    }
    xml = moved + xml.mid(from);
    xml = replaceUrdfAttribute(
        xml, QStringLiteral("dynamics"), QStringLiteral("friction"),
        [](int j, const QString &) { return urdfNumber(kRobotACoulomb[j % 7]); });
    return replaceUrdfAttribute(
        xml, QStringLiteral("dynamics"), QStringLiteral("damping"),
        [](int, const QString &v) { return urdfNumber(v.toDouble() * 1.5); });
}

} // namespace learnid::support
