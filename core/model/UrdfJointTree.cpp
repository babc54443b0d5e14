#include "model/UrdfJointTree.h"

#include "model/Error.h"

#include <QCoreApplication>
#include <QHash>
#include <QSet>
#include <QStringList>
#include <QXmlStreamReader>

namespace learnid {

namespace {

struct Text
{
    Q_DECLARE_TR_FUNCTIONS(UrdfJointTree)
};

struct JointLinks
{
    QString joint;
    QString parent;
    QString child;
};

QString quoted(const QStringList &names)
{
    QStringList out;
    for (const QString &n : names)
        out << QLatin1Char('"') + n + QLatin1Char('"');
    return out.join(QLatin1String(", "));
}

// The joints directly below <robot>, with the link attribute of their first <parent> and
// <child>, as urdfdom takes them.
QList<JointLinks> readJoints(const QByteArray &text, const QString &source)
{
    QList<JointLinks> joints;
    QXmlStreamReader xml(text);
    xml.setNamespaceProcessing(false); // urdfdom does not bind prefixes either
    int depth = 0;
    bool inRobot = false;
    JointLinks *joint = nullptr;
    while (!xml.atEnd()) {
        const QXmlStreamReader::TokenType token = xml.readNext();
        if (token == QXmlStreamReader::StartElement) {
            ++depth;
            const QStringView name = xml.qualifiedName();
            if (depth == 1) {
                inRobot = name == QLatin1String("robot");
            } else if (depth == 2 && inRobot && name == QLatin1String("joint")) {
                joints.append({xml.attributes().value(QLatin1String("name")).toString(), {}, {}});
                joint = &joints.back();
            } else if (depth == 3 && joint) {
                QString *link = name == QLatin1String("parent")  ? &joint->parent
                                : name == QLatin1String("child") ? &joint->child
                                                                 : nullptr;
                if (link && link->isNull())
                    *link = xml.attributes().value(QLatin1String("link")).toString();
            }
        } else if (token == QXmlStreamReader::EndElement) {
            if (depth == 2)
                joint = nullptr;
            --depth;
        }
    }
    if (xml.hasError()) {
        throw Error(Text::tr("%1: line %2, column %3: not well-formed XML: %4")
                        .arg(source, QString::number(xml.lineNumber()),
                             QString::number(xml.columnNumber()), xml.errorString()));
    }
    return joints;
}

} // namespace

void checkUrdfJointTree(const QByteArray &text, const QString &source)
{
    QHash<QString, const JointLinks *> parentJoint; // by child link
    const QList<JointLinks> joints = readJoints(text, source);
    for (const JointLinks &j : joints) {
        if (j.parent.isEmpty() || j.child.isEmpty())
            continue;
        if (j.parent == j.child) {
            throw Error(Text::tr("%1: joint \"%2\" connects link \"%3\" to itself")
                            .arg(source, j.joint, j.child));
        }
        if (const JointLinks *other = parentJoint.value(j.child)) {
            throw Error(Text::tr("%1: link \"%2\" is the child of two joints, \"%3\" and \"%4\": "
                                 "the joints of a URDF form a tree")
                            .arg(source, j.child, other->joint, j.joint));
        }
        parentJoint.insert(j.child, &j);
    }
    // Each link has at most one parent now, so a walk up either ends or runs into a loop.
    QSet<QString> done;                  // links whose walk up ends at a root
    for (const JointLinks &j : joints) { // in the file's order, so the message is the same
        QStringList walk;                // every time
        QString link = j.child;
        while (!done.contains(link) && parentJoint.contains(link)) {
            if (const qsizetype at = walk.indexOf(link); at >= 0) {
                throw Error(Text::tr("%1: the joints form a loop through links %2: the joints of "
                                     "a URDF form a tree")
                                .arg(source, quoted(walk.mid(at))));
            }
            walk << link;
            link = parentJoint.value(link)->parent;
        }
        for (const QString &l : walk)
            done.insert(l);
    }
}

} // namespace learnid
