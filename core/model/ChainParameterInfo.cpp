#include "model/ChainParameterInfo.h"

#include <QCoreApplication>

namespace learnid {

namespace {

struct Text
{
    Q_DECLARE_TR_FUNCTIONS(ChainModel)
};

QString subscript(int number)
{
    QString digits = QString::number(number);
    for (QChar &c : digits)
        c = QChar(0x2080 + (c.unicode() - '0'));
    return digits;
}

} // namespace

QList<ParameterInfo> standardParameterInfo(const SerialChain &chain, const JointTerms &terms)
{
    const QString kg = QStringLiteral("kg"), kgm = QStringLiteral("kg m"),
                  kgm2 = QStringLiteral("kg m^2");
    QList<ParameterInfo> info;
    for (int k = 0; k < chain.dof(); ++k) {
        const QString s = subscript(k + 1);
        const QString link = chain.joints[size_t(k)].link;
        const QString group = Text::tr("link %1 (%2)").arg(k + 1).arg(link);
        info.append({QStringLiteral("m") + s, kg, Text::tr("mass of link %1").arg(link), group});
        for (const char *axis : {"x", "y", "z"}) {
            info.append({QStringLiteral("m·c%1").arg(QLatin1String(axis)) + s, kgm,
                         Text::tr("first moment of mass of link %1 along its %2 axis")
                             .arg(link, QLatin1String(axis)),
                         group});
        }
        for (const char *pair : {"xx", "xy", "yy", "xz", "yz", "zz"}) {
            info.append({QStringLiteral("I%1").arg(QLatin1String(pair)) + s, kgm2,
                         Text::tr("inertia %1 of link %2 about its frame origin")
                             .arg(QLatin1String(pair), link),
                         group});
        }
    }
    for (int k = 0; k < chain.dof(); ++k) {
        const QString s = subscript(k + 1);
        const QString joint = chain.joints[size_t(k)].name;
        const QString group = Text::tr("joint %1 (%2)").arg(k + 1).arg(joint);
        const bool prismatic = chain.joints[size_t(k)].type == JointType::Prismatic;
        const QString force = prismatic ? QStringLiteral("N") : QStringLiteral("N m");
        if (terms.armature)
            info.append({QStringLiteral("Ia") + s, prismatic ? kg : kgm2,
                         Text::tr("rotor inertia at joint %1").arg(joint), group});
        if (terms.viscous)
            info.append({QStringLiteral("fv") + s,
                         prismatic ? QStringLiteral("N s/m") : QStringLiteral("N m s/rad"),
                         Text::tr("viscous friction of joint %1").arg(joint), group});
        if (terms.coulomb)
            info.append({QStringLiteral("fc") + s, force,
                         Text::tr("Coulomb friction of joint %1").arg(joint), group});
        if (terms.offset)
            info.append({QStringLiteral("τo") + s, force,
                         Text::tr("torque offset of joint %1").arg(joint), group});
    }
    return info;
}

} // namespace learnid
