#include "canrobot/JointIdentityCheck.h"

#include "can/CanOpen.h"
#include "can/JointIdentity.h"

#include <QCoreApplication>
#include <QStringList>

namespace learnid {

namespace {

struct Text
{
    Q_DECLARE_TR_FUNCTIONS(CanRobot)
};

// A read of an UNSIGNED32 (or shorter) value into *target.
SdoStep readInto(quint8 node, quint16 index, quint8 sub, quint32 *target)
{
    return SdoStep::read(node, index, sub, [node, index, sub, target](const QByteArray &data) {
        if (data.isEmpty() || data.size() > 4)
            return Text::tr("node %1, object %2: the answer holds %3 bytes, 1 to 4 expected")
                .arg(node)
                .arg(canopen::objectAddress(index, sub))
                .arg(data.size());
        QByteArray padded = data;
        padded.resize(4, '\0');
        *target = canopen::readU32(padded, 0);
        return QString();
    });
}

QString hex(quint32 v)
{
    return QStringLiteral("0x%1").arg(v, 8, 16, QLatin1Char('0'));
}

} // namespace

QList<SdoStep> jointIdentityReads(const QList<int> &nodes,
                                  std::shared_ptr<JointIdentityFound> found)
{
    const int n = int(nodes.size());
    found->drives = QVector<DriveIdentity>(n);
    found->robot = QVector<quint32>(n, 0);
    found->joint = QVector<int>(n, 0);
    QList<SdoStep> steps;
    for (int j = 0; j < n; ++j) {
        const auto node = quint8(nodes[j]);
        DriveIdentity *d = &found->drives[j];
        steps << readInto(node, objects::identityObject, 1, &d->vendorId)
              << readInto(node, objects::identityObject, 2, &d->productCode)
              << readInto(node, objects::identityObject, 3, &d->revision)
              << readInto(node, objects::identityObject, 4, &d->serialNumber)
              << readInto(node, objects::jointIdentity, objects::jointIdentityRobot,
                          &found->robot[j]);
        steps << SdoStep::read(node, objects::jointIdentity, objects::jointIdentityJoint,
                               [found, j](const QByteArray &data) {
                                   found->joint[j] = data.isEmpty() ? 0 : quint8(data.at(0));
                                   return QString();
                               });
    }
    return steps;
}

QString jointIdentityError(const QList<int> &nodes, const JointIdentityFound &found,
                           const JointIdentityExpectation &expected)
{
    const int n = int(nodes.size());
    // A node list that does not match the wiring: refused whatever the technician confirmed.
    for (int j = 0; j < n; ++j) {
        if (found.robot[j] != expected.robot || found.joint[j] == j + 1)
            continue;
        // The list the drives give, when every one of them is a joint of this robot.
        QList<int> wired(n, 0);
        for (int k = 0; k < n; ++k) {
            if (found.robot[k] == expected.robot && found.joint[k] >= 1 && found.joint[k] <= n)
                wired[found.joint[k] - 1] = nodes[k];
        }
        QString hint;
        if (!wired.contains(0)) {
            QStringList ids;
            for (const int node : wired)
                ids << QString::number(node);
            hint = Text::tr("; the drives say --nodes %1").arg(ids.join(QLatin1Char(',')));
        }
        return Text::tr("node %1 is listed for joint %2 but is the drive of joint %3 of this robot "
                        "(0x2400:02 = %3): the node list does not match the wiring%4")
            .arg(nodes[j])
            .arg(j + 1)
            .arg(found.joint[j])
            .arg(hint);
    }
    if (!expected.recordedDrives.isEmpty()) {
        for (int j = 0; j < n && j < expected.recordedDrives.size(); ++j) {
            if (found.drives[j] != expected.recordedDrives[j])
                return Text::tr("node %1 (joint %2) is not the drive the parameter file records "
                                "for joint %2: it reports %3 (0x1018), the file holds %4")
                    .arg(nodes[j])
                    .arg(j + 1)
                    .arg(found.drives[j].text(), expected.recordedDrives[j].text());
        }
    }
    if (expected.commissioning)
        return {};
    for (int j = 0; j < n; ++j) {
        if (found.robot[j] == 0)
            return Text::tr("node %1 (joint %2) has never been commissioned (0x2400 is 0), so "
                            "learnid cannot check which joint it moves: make sure it is the "
                            "drive of joint %2 (its identity: %3), then run with --commission (in "
                            "the window: First commissioning); apply stores the joint identity")
                .arg(nodes[j])
                .arg(j + 1)
                .arg(found.drives[j].text());
        if (found.robot[j] != expected.robot)
            return Text::tr("node %1 (joint %2) was commissioned for another robot (0x2400:01 = "
                            "%3, this robot is %4): make sure it is the drive of joint %2 (%5), "
                            "then run with --commission (in the window: First commissioning)")
                .arg(nodes[j])
                .arg(j + 1)
                .arg(hex(found.robot[j]), hex(expected.robot), found.drives[j].text());
    }
    return {};
}

} // namespace learnid
