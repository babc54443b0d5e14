#include "model/ModelFactory.h"

#include "model/ChainModel.h"
#include "model/Error.h"
#include "model/TwoLinkArm.h"
#include "model/UrdfChain.h"

#include <QCoreApplication>
#include <QCryptographicHash>
#include <QFile>
#include <QFileInfo>
#include <QHash>
#include <mutex>

namespace learnid {

namespace {

const QString urdfId = QStringLiteral("urdf");

QStringList builtInUrdfRobots()
{
    return {QStringLiteral("paper-2link-urdf"), QStringLiteral("double-pendulum"),
            QStringLiteral("puma560"), QStringLiteral("panda")};
}

// Everything a chain model depends on, the URDF by its contents (a file edited between two
// sessions gives a new model).
QByteArray cacheKey(const QString &id, const QByteArray &xml, const UrdfRobotSettings &urdf)
{
    const JointTerms &t = urdf.jointTerms;
    QByteArray key = QCryptographicHash::hash(xml, QCryptographicHash::Sha256);
    key += id.toUtf8() + '\n' + urdf.baseLink.toUtf8() + '\n' + urdf.tipLink.toUtf8() + '\n';
    for (const double v : {urdf.gravity.x(), urdf.gravity.y(), urdf.gravity.z(), t.coulombVelocity})
        key += QByteArray::number(v, 'g', 17) + ' ';
    key += QByteArray::number(int(t.armature) | int(t.viscous) << 1 | int(t.coulomb) << 2 |
                              int(t.offset) << 3);
    return key;
}

} // namespace

QStringList knownRobotModels()
{
    return QStringList{QStringLiteral("paper-2link"), urdfId} + builtInUrdfRobots();
}

bool isUrdfModel(const QString &id)
{
    return id == urdfId || builtInUrdfRobots().contains(id);
}

QString urdfFileOf(const QString &id, const UrdfRobotSettings &urdf)
{
    if (id == urdfId)
        return urdf.file;
    // The paper's arm as a URDF is "paper-2link-urdf": "paper-2link" is its closed form.
    QString name = id;
    name.remove(QLatin1String("-urdf"));
    return QStringLiteral(":/robots/%1.urdf").arg(name);
}

std::shared_ptr<const RobotModel> makeRobotModel(const QString &id, const UrdfRobotSettings &urdf)
{
    if (id == QLatin1String("paper-2link"))
        return std::make_shared<TwoLinkArm>();
    if (!isUrdfModel(id))
        return nullptr;
    const QString path = urdfFileOf(id, urdf);
    if (path.isEmpty()) {
        throw Error(QCoreApplication::translate("ModelFactory",
                                                "robot.urdf.file: the \"urdf\" model needs a URDF "
                                                "file"));
    }
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        throw Error(QCoreApplication::translate("ModelFactory", "%1: cannot read the URDF: %2")
                        .arg(path, file.errorString()));
    }
    const QByteArray xml = file.readAll();
    static std::mutex cacheMutex;
    static QHash<QByteArray, std::shared_ptr<const RobotModel>> cache;
    const QByteArray key = cacheKey(id, xml, urdf);
    {
        const std::lock_guard<std::mutex> lock(cacheMutex);
        if (const auto found = cache.constFind(key); found != cache.constEnd())
            return found.value();
    }
    SerialChain chain =
        parseUrdfChain(xml, path, urdf.baseLink, urdf.tipLink, QFileInfo(path).absolutePath());
    chain.gravity = urdf.gravity;
    auto model = std::make_shared<const ChainModel>(chain, urdf.jointTerms, id);
    const std::lock_guard<std::mutex> lock(cacheMutex);
    cache.insert(key, model);
    return model;
}

} // namespace learnid
