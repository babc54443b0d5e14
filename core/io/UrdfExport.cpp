#include "io/UrdfExport.h"

#include "model/Error.h"
#include "model/PhysicalConsistency.h"
#include "model/UrdfChain.h"
#include "model/UrdfExtension.h"

#include <QCoreApplication>
#include <QDomDocument>
#include <QHash>
#include <QList>
#include <QLocale>
#include <QStringList>
#include <QXmlStreamWriter>
#include <algorithm>
#include <cmath>
#include <utility>

// The original document is edited, not regenerated: only <inertial>, <dynamics> and learnid's
// extension element (UrdfExtension.h) change.
// The comment written into the file is not translated: it is part of the file, read by whoever
// opens it next, as the DCF fragment's text is (ParameterDcf.cpp).

namespace learnid {

namespace {

struct Text
{
    Q_DECLARE_TR_FUNCTIONS(UrdfExport)
};

// The shortest text that reads back to the same double (urdfdom reads with the C locale).
QString number(double v)
{
    return QString::number(v, 'g', QLocale::FloatingPointShortest);
}

QString vectorText(const Eigen::Vector3d &v)
{
    return number(v.x()) + QLatin1Char(' ') + number(v.y()) + QLatin1Char(' ') + number(v.z());
}

QString jointLink(const QDomElement &joint, const char *end)
{
    return joint.firstChildElement(QLatin1String(end)).attribute(QStringLiteral("link"));
}

bool isFixed(const QDomElement &joint)
{
    return joint.attribute(QStringLiteral("type")) == QLatin1String("fixed");
}

// The links and joints of the document: the direct children of <robot>, as urdfdom reads them
// (the <joint> inside a <transmission> is not one).
struct UrdfTree
{
    QHash<QString, QDomElement> links;
    QHash<QString, QDomElement> parentJoint;        // child link -> the joint above it
    QHash<QString, QList<QDomElement>> childJoints; // parent link -> the joints below it, in order
};

UrdfTree indexTree(const QDomElement &robot)
{
    UrdfTree tree;
    const QString link = QStringLiteral("link");
    const QString joint = QStringLiteral("joint");
    for (QDomElement e = robot.firstChildElement(link); !e.isNull(); e = e.nextSiblingElement(link))
        tree.links.insert(e.attribute(QStringLiteral("name")), e);
    for (QDomElement e = robot.firstChildElement(joint); !e.isNull();
         e = e.nextSiblingElement(joint)) {
        tree.parentJoint.insert(jointLink(e, "child"), e);
        tree.childJoints[jointLink(e, "parent")].append(e);
    }
    return tree;
}

// Every link fixed to `link`, directly or through other fixed joints, except `next` (the
// chain's next link): UrdfChain.cpp's mergeFixedChildren().
void addFixedDescendants(const UrdfTree &tree, const QString &link, const QString &next,
                         QStringList &out)
{
    for (const QDomElement &joint : tree.childJoints.value(link)) {
        const QString child = jointLink(joint, "child");
        if (child == next || !isFixed(joint))
            continue;
        out << child;
        addFixedDescendants(tree, child, QString(), out);
    }
}

// For each moving joint, the links whose inertia readUrdfChain() merged into its body, found by
// the same walk from the base to the tip (UrdfChain.cpp's parseUrdfChain()): the fixed links on
// the chain up to the next moving joint, and the links fixed to any of these off the chain.
// The chain was read from this document, so the walk reaches the base.
std::vector<QStringList> mergedLinks(const UrdfTree &tree, const SerialChain &chain)
{
    QStringList path; // below the base, down to the tip
    for (QString link = chain.tipLink; link != chain.baseLink && tree.parentJoint.contains(link);
         link = jointLink(tree.parentJoint.value(link), "parent")) {
        path.prepend(link);
    }
    std::vector<QStringList> merged(chain.joints.size());
    int body = -1; // the moving body the walk is in; links fixed to the base are none
    for (int i = 0; i < path.size(); ++i) {
        if (!isFixed(tree.parentJoint.value(path[i])))
            ++body;
        else if (body >= 0)
            merged.at(body) << path[i];
        if (body >= 0)
            addFixedDescendants(tree, path[i], i + 1 < path.size() ? path[i + 1] : QString(),
                                merged.at(body));
    }
    return merged;
}

// The bodies must be physical (URDF has no other) and the friction coefficients dissipative.
void checkJoint(const ChainJoint &joint, const InertialParameters &pi, const IdentifiedJoint &f,
                const QString &source)
{
    if (!pi.allFinite()) {
        throw Error(Text::tr("%1: link \"%2\": the identified body has an entry that is not a "
                             "finite number")
                        .arg(source, joint.link));
    }
    if (!(pi[0] > 0.0)) {
        throw Error(Text::tr("%1: link \"%2\": the identified mass (%3 kg) is not positive")
                        .arg(source, joint.link, number(pi[0])));
    }
    const LinkConsistency verdict = checkConsistency(Eigen::VectorXd(pi), 1, 1e-12).front();
    if (!verdict.consistent) {
        throw Error(Text::tr("%1: link \"%2\": the identified inertia is not that of a physical "
                             "body (its pseudo-inertia has the negative eigenvalue %3)")
                        .arg(source, joint.link, number(verdict.minEigenvalue)));
    }
    if (!(std::isfinite(f.viscous) && f.viscous >= 0.0 && std::isfinite(f.coulomb) &&
          f.coulomb >= 0.0)) {
        throw Error(Text::tr("%1: joint \"%2\": the friction must be finite and not negative, got "
                             "viscous %3 and Coulomb %4")
                        .arg(source, joint.name, number(f.viscous), number(f.coulomb)));
    }
    if (!(std::isfinite(f.armature) && f.armature >= 0.0 && std::isfinite(f.offset))) {
        throw Error(Text::tr("%1: joint \"%2\": the armature must be finite and not negative and "
                             "the offset finite, got armature %3 and offset %4")
                        .arg(source, joint.name, number(f.armature), number(f.offset)));
    }
}

// <inertial> of the body pi about its centre of mass c = h / m, axes as the link frame's:
// I_c = I_O - m (|c|^2 E - c c^T), the parallel axis theorem backwards.
QDomElement inertialElement(QDomDocument &doc, const InertialParameters &pi)
{
    const double m = pi[0];
    const Eigen::Vector3d c = pi.segment<3>(1) / m;
    const Eigen::Matrix3d ic =
        rotationalInertia(pi) -
        m * (c.squaredNorm() * Eigen::Matrix3d::Identity() - c * c.transpose());
    QDomElement inertial = doc.createElement(QStringLiteral("inertial"));
    QDomElement origin = doc.createElement(QStringLiteral("origin"));
    origin.setAttribute(QStringLiteral("xyz"), vectorText(c));
    origin.setAttribute(QStringLiteral("rpy"), QStringLiteral("0 0 0"));
    QDomElement mass = doc.createElement(QStringLiteral("mass"));
    mass.setAttribute(QStringLiteral("value"), number(m));
    QDomElement inertia = doc.createElement(QStringLiteral("inertia"));
    const std::pair<const char *, double> entries[] = {{"ixx", ic(0, 0)}, {"ixy", ic(0, 1)},
                                                       {"ixz", ic(0, 2)}, {"iyy", ic(1, 1)},
                                                       {"iyz", ic(1, 2)}, {"izz", ic(2, 2)}};
    for (const auto &[name, value] : entries)
        inertia.setAttribute(QLatin1String(name), number(value));
    inertial.appendChild(origin);
    inertial.appendChild(mass);
    inertial.appendChild(inertia);
    return inertial;
}

// Puts `inertial` in place of link's first <inertial> and removes the others (urdfdom reads the
// first only); a null `inertial` removes them all.
void setInertial(QDomElement link, const QDomElement &inertial = QDomElement())
{
    const QString tag = QStringLiteral("inertial");
    const QDomElement old = link.firstChildElement(tag);
    if (!inertial.isNull() && old.isNull())
        link.insertBefore(inertial, link.firstChild());
    else if (!inertial.isNull())
        link.replaceChild(inertial, old);
    for (QDomElement e = link.firstChildElement(tag); !e.isNull();) {
        const QDomElement next = e.nextSiblingElement(tag);
        if (e != inertial)
            link.removeChild(e);
        e = next;
    }
}

void setDynamics(QDomDocument &doc, QDomElement joint, const IdentifiedJoint &f)
{
    QDomElement dynamics = joint.firstChildElement(QStringLiteral("dynamics"));
    if (dynamics.isNull())
        dynamics = joint.appendChild(doc.createElement(QStringLiteral("dynamics"))).toElement();
    dynamics.setAttribute(QStringLiteral("damping"), number(f.viscous));
    dynamics.setAttribute(QStringLiteral("friction"), number(f.coulomb));
}

// learnid's element for armature and offset, after <dynamics>; written where either is not 0 or
// the joint had one (a model without these terms then writes 0, which it used). Returns whether
// the joint has one now.
bool setExtension(QDomDocument &doc, QDomElement joint, const IdentifiedJoint &f)
{
    const QString tag = QLatin1String(urdfExtensionElement);
    QDomElement e = joint.firstChildElement(tag);
    if (e.isNull() && f.armature == 0.0 && f.offset == 0.0)
        return false;
    if (e.isNull()) {
        e = doc.createElement(tag);
        joint.insertAfter(e, joint.firstChildElement(QStringLiteral("dynamics")));
    }
    e.setAttribute(QStringLiteral("armature"), number(f.armature));
    e.setAttribute(QStringLiteral("offset"), number(f.offset));
    return true;
}

QString commentText(const QStringList &lines)
{
    QString text = QLatin1Char(' ') + lines.join(QLatin1String("\n     ")) + QLatin1Char(' ');
    while (text.contains(QLatin1String("--"))) // not allowed in an XML comment
        text.replace(QLatin1String("--"), QLatin1String("- -"));
    return text;
}

QString fileComment(const QString &comment, const SerialChain &chain,
                    const std::vector<QStringList> &merged)
{
    QStringList lines = {
        QStringLiteral(
            "Inertial parameters and joint <dynamics> identified by learnid; the rest is"),
        QStringLiteral("the original URDF. Each moving link's <inertial> is its whole rigid body,"),
        QStringLiteral("about its centre of mass; links fixed to it were merged into it and lost"),
        QStringLiteral("their own <inertial>, their mass is in the moving link's:")};
    for (size_t j = 0; j < merged.size(); ++j) {
        if (!merged[j].isEmpty())
            lines << QStringLiteral("  into %1: %2")
                         .arg(chain.joints[j].link, merged[j].join(QLatin1String(", ")));
    }
    lines << QStringLiteral("<dynamics damping> is the viscous friction [N m s/rad or N s/m],")
          << QStringLiteral("friction the Coulomb friction [N m or N]. URDF has no place for a")
          << QStringLiteral("joint's rotor inertia and torque offset: learnid writes them as")
          << QStringLiteral("<learnid:dynamics armature=\"kg m^2 or kg\" offset=\"N m or N\"/> in")
          << QStringLiteral("the joint, an element other URDF parsers skip.");
    if (!comment.isEmpty())
        lines.prepend(comment);
    return commentText(lines);
}

// Qt's DOM keeps attributes in a hash: written in name order, the output is the same every time.
void writeNode(QXmlStreamWriter &out, const QDomNode &node)
{
    switch (node.nodeType()) {
    case QDomNode::ElementNode: {
        out.writeStartElement(node.nodeName());
        const QDomNamedNodeMap map = node.attributes();
        std::vector<std::pair<QString, QString>> attributes;
        for (int i = 0; i < map.count(); ++i)
            attributes.emplace_back(map.item(i).nodeName(), map.item(i).nodeValue());
        std::sort(attributes.begin(), attributes.end());
        for (const auto &[name, value] : attributes)
            out.writeAttribute(name, value);
        for (QDomNode child = node.firstChild(); !child.isNull(); child = child.nextSibling())
            writeNode(out, child);
        out.writeEndElement();
        break;
    }
    case QDomNode::TextNode:
        out.writeCharacters(node.nodeValue());
        break;
    case QDomNode::CDATASectionNode:
        out.writeCDATA(node.nodeValue());
        break;
    case QDomNode::CommentNode:
        out.writeComment(node.nodeValue());
        break;
    case QDomNode::ProcessingInstructionNode: // the XML declaration is the writer's own
        if (node.nodeName() != QLatin1String("xml"))
            out.writeProcessingInstruction(node.nodeName(), node.nodeValue());
        break;
    default:
        break;
    }
}

// The written text must read back as written: this holds the walk above to urdfdom's reading.
void verifyWritten(const QByteArray &xml, const QString &source, const SerialChain &chain,
                   const std::vector<InertialParameters> &inertials,
                   const std::vector<IdentifiedJoint> &friction)
{
    const SerialChain read = parseUrdfChain(xml, source, chain.baseLink, chain.tipLink);
    for (int j = 0; j < chain.dof(); ++j) {
        const InertialParameters &pi = inertials[j];
        const ChainJoint &joint = read.joints.at(j);
        if ((joint.inertial - pi).cwiseAbs().maxCoeff() > 1e-9 * pi.cwiseAbs().maxCoeff() ||
            joint.damping != friction[j].viscous || joint.friction != friction[j].coulomb ||
            joint.armature != friction[j].armature || joint.offset != friction[j].offset) {
            throw Error(Text::tr("%1: the identified URDF reads back with another body or "
                                 "friction at link \"%2\" than was written")
                            .arg(source, joint.link));
        }
    }
}

} // namespace

QByteArray identifiedUrdf(const QByteArray &originalXml, const QString &source,
                          const SerialChain &chain,
                          const std::vector<InertialParameters> &inertials,
                          const std::vector<IdentifiedJoint> &friction, const QString &comment,
                          const QStringList &notes)
{
    if (inertials.size() != chain.joints.size() || friction.size() != chain.joints.size()) {
        throw Error(Text::tr("%1: bodies for %2 and friction for %3 joints given, the chain has "
                             "%4 moving joints")
                        .arg(source, QString::number(inertials.size()),
                             QString::number(friction.size()), QString::number(chain.dof())));
    }
    // The links merged below are the ones readUrdfChain() merged only if chain is this text's.
    const auto jointNames = [](const SerialChain &c) {
        QStringList names;
        for (const ChainJoint &joint : c.joints)
            names << joint.name;
        return names.join(QLatin1String(", "));
    };
    const SerialChain original = parseUrdfChain(originalXml, source, chain.baseLink, chain.tipLink);
    if (jointNames(chain) != jointNames(original)) {
        throw Error(Text::tr("%1: the chain's moving joints (%2) are not the URDF's from link "
                             "\"%3\" to link \"%4\" (%5): the chain was not read from this URDF")
                        .arg(source, jointNames(chain), chain.baseLink, chain.tipLink,
                             jointNames(original)));
    }
    for (int j = 0; j < chain.dof(); ++j)
        checkJoint(chain.joints[j], inertials[j], friction[j], source);

    QDomDocument doc;
    QString message;
    int line = 0;
    int column = 0;
    if (!doc.setContent(originalXml, false, &message, &line, &column)) {
        throw Error(Text::tr("%1: line %2, column %3: not XML: %4")
                        .arg(source, QString::number(line), QString::number(column), message));
    }
    const UrdfTree tree = indexTree(doc.documentElement());
    const std::vector<QStringList> merged = mergedLinks(tree, chain);
    bool extended = false;
    for (int j = 0; j < chain.dof(); ++j) {
        const ChainJoint &joint = chain.joints[j];
        setInertial(tree.links.value(joint.link), inertialElement(doc, inertials[j]));
        for (const QString &link : merged[j])
            setInertial(tree.links.value(link));
        setDynamics(doc, tree.parentJoint.value(joint.link), friction[j]);
        extended |= setExtension(doc, tree.parentJoint.value(joint.link), friction[j]);
    }
    if (extended) {
        doc.documentElement().setAttribute(QStringLiteral("xmlns:") +
                                               QLatin1String(urdfExtensionPrefix),
                                           QLatin1String(urdfExtensionNamespace));
    }

    QByteArray xml;
    QXmlStreamWriter out(&xml);
    out.setAutoFormatting(true);
    out.setAutoFormattingIndent(2);
    out.writeStartDocument();
    out.writeComment(fileComment(comment, chain, merged));
    if (!notes.isEmpty())
        out.writeComment(commentText(notes));
    for (QDomNode node = doc.firstChild(); !node.isNull(); node = node.nextSibling())
        writeNode(out, node);
    out.writeEndDocument();
    verifyWritten(xml, source, chain, inertials, friction);
    return xml;
}

} // namespace learnid
