#include "model/ModelCheck.h"

#include "model/CadPrior.h"
#include "model/ChainModel.h"
#include "model/PhysicalConsistency.h"

#include <QCoreApplication>

namespace learnid {

namespace {

struct Text
{
    Q_DECLARE_TR_FUNCTIONS(ModelCheck)
};

QString number(double v)
{
    return QString::number(v, 'g', 3);
}

QString linkName(const SerialChain &chain, int l)
{
    return Text::tr("link %1 (%2)").arg(l + 1).arg(chain.joints[size_t(l)].link);
}

QString jointName(const SerialChain &chain, int j)
{
    return Text::tr("joint %1 (%2)").arg(j + 1).arg(chain.joints[size_t(j)].name);
}

// The plausibility problems of one real body, one line each.
QStringList plausibilityLines(const QString &link, const LinkPlausibility &v,
                              const std::optional<BoundingEllipsoid> &volume,
                              const PlausibilityRule &rule)
{
    QStringList out;
    if (!v.momentsOk) {
        out << Text::tr("%1: its smallest principal moment of inertia about the centre of mass, "
                        "%2 kg m^2, is below %3 % of the CAD link's smallest (%4 kg m^2): a point "
                        "mass or a needle, not a link")
                   .arg(link, number(v.moments[0]), number(100.0 * rule.minMomentShare),
                        number(v.cadSmallestMoment));
    }
    if (!v.triangleOk) {
        out << Text::tr("%1: its principal moments %2, %3 and %4 kg m^2 give I1 + I2 = %5 I3, "
                        "below %6 I3 (a flat plate at best)")
                   .arg(link, number(v.moments[0]), number(v.moments[1]), number(v.moments[2]),
                        QString::number(v.triangleRatio, 'f', 3),
                        QString::number(1.0 + rule.triangleMargin, 'f', 3));
    }
    if (!v.volumeOk && volume) {
        out << Text::tr("%1: its centre of mass lies outside its bounding volume (%2)")
                   .arg(link, volume->source == VolumeSource::Geometry
                                  ? Text::tr("the URDF's geometry: %1").arg(volume->description)
                                  : Text::tr("the CAD body's inertia ellipsoid, enlarged %1 times")
                                        .arg(cadVolumeMargin));
    }
    return out;
}

} // namespace

QStringList modelProblems(const ChainModel &model, const SerialChain &chain,
                          const Eigen::VectorXd &cadPrior, const PlausibilityRule &rule)
{
    const int n = model.dof();
    const Eigen::VectorXd standard = model.standardOf(chain);
    QStringList out;
    const std::vector<LinkConsistency> consistency = checkConsistency(standard, n, 1e-12);
    const auto volumes = linkVolumes(model.chain(), cadPrior);
    const std::vector<LinkPlausibility> plausibility =
        checkPlausibility(standard, cadPrior, n, volumes, rule);
    for (int l = 0; l < n; ++l) {
        const LinkConsistency &c = consistency[size_t(l)];
        if (!(c.mass > 0.0)) {
            out << Text::tr("%1: its mass is %2 kg: not a real body")
                       .arg(linkName(chain, l), number(c.mass));
        } else if (!c.consistent) {
            out << Text::tr("%1: no mass distribution has its inertia (its pseudo-inertia has the "
                            "negative eigenvalue %2): not a real body")
                       .arg(linkName(chain, l), number(c.minEigenvalue));
        } else {
            out += plausibilityLines(linkName(chain, l), plausibility[size_t(l)],
                                     volumes[size_t(l)], rule);
        }
    }
    for (int j = 0; j < n; ++j) {
        const ChainJoint &joint = chain.joints[size_t(j)];
        const std::pair<const char *, double> terms[] = {
            {"<dynamics damping>", joint.damping},
            {"<dynamics friction>", joint.friction},
            {"<learnid:dynamics armature>", joint.armature}};
        for (const auto &[name, value] : terms) {
            if (value < 0.0) {
                out << Text::tr("%1: %2 is %3, negative: friction and rotor inertia take energy, "
                                "they do not give it")
                           .arg(jointName(chain, j), QLatin1String(name), number(value));
            }
        }
    }
    return out;
}

QStringList modelWarnings(const ChainModel &model)
{
    return modelProblems(model, model.chain(), realBodyPrior(model.cadStandard(), model.dof()));
}

} // namespace learnid
