#include "service/PayloadArm.h"

#include "io/AtomicFile.h"
#include "io/JsonReader.h"
#include "io/ParameterFile.h"
#include "model/Error.h"
#include "model/ModelFactory.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>

namespace learnid {

namespace {

struct Text
{
    Q_DECLARE_TR_FUNCTIONS(PayloadArm)
};

// The joint terms whose parameters the file lists (ChainParameterInfo.h names them).
JointTerms termsOf(const QList<ParameterInfo> &standard)
{
    JointTerms terms{false, false, false, false};
    for (const ParameterInfo &p : standard) {
        terms.armature |= p.name.startsWith(QLatin1String("Ia"));
        terms.viscous |= p.name.startsWith(QLatin1String("fv"));
        terms.coulomb |= p.name.startsWith(QLatin1String("fc"));
        terms.offset |= p.name.startsWith(QStringLiteral("τo"));
    }
    return terms;
}

PayloadArm armFromFile(const LogIdentificationRequest &request, const QString &armUrdf,
                       const QString &armUrdfName)
{
    const QString path = QDir::toNativeSeparators(request.robot);
    const ParameterFileContent file = readParameterFile(request.robot);
    if (file.standardParameters.isEmpty()) {
        throw Error(Text::tr("%1: standardParameters: is empty (robot.model %2): the arm's model "
                             "for a payload is the whole model as standard parameters, as "
                             "`learnid-cli identify --export` writes it for a URDF robot")
                        .arg(path, file.robotModel));
    }
    LogIdentificationRequest urdf = request;
    urdf.terms = termsOf(file.standardParameters);
    if (file.robotModel == QLatin1String("urdf")) {
        if (armUrdf.isEmpty()) {
            throw Error(Text::tr("%1: robot.model is \"urdf\": the file does not carry its URDF; "
                                 "give the URDF the arm was identified on with %2")
                            .arg(path, armUrdfName));
        }
        urdf.robot = armUrdf;
    } else if (!armUrdf.isEmpty()) {
        throw Error(Text::tr("%1: only for a parameter file of robot.model \"urdf\"; %2 is of "
                             "the built-in %3, whose URDF is known")
                        .arg(armUrdfName, path, file.robotModel));
    } else {
        urdf.robot = file.robotModel; // a built-in: its own URDF (the file was checked: known)
    }
    PayloadArm arm;
    arm.robot = loadLogRobot(urdf);
    const QList<ParameterInfo> names = arm.robot.model->standardParameters();
    const int p = int(file.standardParameters.size());
    if (names.size() != p) {
        throw Error(Text::tr("%1: standardParameters: has %2 entries, the arm's model from %3 "
                             "has %4: the file was not identified on this URDF (or with other "
                             "base and tip links)")
                        .arg(path)
                        .arg(p)
                        .arg(arm.robot.source)
                        .arg(names.size()));
    }
    for (int i = 0; i < p; ++i) {
        if (names.at(i).name != file.standardParameters.at(i).name) {
            throw Error(
                Text::tr("%1: standardParameters[%2].name: is \"%3\", the arm's model "
                         "from %4 has \"%5\" there: the file was not identified on this "
                         "URDF")
                    .arg(path)
                    .arg(i)
                    .arg(file.standardParameters.at(i).name, arm.robot.source, names.at(i).name));
        }
    }
    if (file.payload) {
        try {
            checkPayloadLink(*file.payload, arm.robot.chain);
        } catch (const Error &e) {
            throw Error(QStringLiteral("%1: %2").arg(path, e.message()));
        }
        arm.notes << Text::tr("%1 holds a payload on %2; it is not part of the arm's model and "
                              "is left out")
                         .arg(path, file.payload->link);
    }
    arm.standard = file.standardValues;
    arm.determined = file.standardDetermined;
    arm.parameterFile = path;
    arm.identified = true;
    return arm;
}

} // namespace

bool looksLikeParameterFile(const QByteArray &head)
{
    const QByteArray text = head.trimmed();
    return text.startsWith('{');
}

PayloadArm loadPayloadArm(const LogIdentificationRequest &request, const QString &armUrdf,
                          const QString &armUrdfName)
{
    if (!builtInUrdfRobots().contains(request.robot) && QFileInfo(request.robot).isFile()) {
        QFile file(request.robot);
        if (file.open(QIODevice::ReadOnly) && looksLikeParameterFile(file.read(256)))
            return armFromFile(request, armUrdf, armUrdfName);
    }
    if (!armUrdf.isEmpty()) {
        throw Error(Text::tr("%1: only for a parameter file of robot.model \"urdf\" given as "
                             "the arm; %2 is a URDF or a built-in robot")
                        .arg(armUrdfName, request.robot));
    }
    PayloadArm arm;
    arm.robot = loadLogRobot(request);
    arm.standard = arm.robot.model->cadStandard();
    // identifiedUrdf()'s comment (English, never translated) says so.
    arm.identified =
        arm.robot.urdf.contains("Inertial parameters and joint <dynamics> identified by learnid");
    return arm;
}

} // namespace learnid
