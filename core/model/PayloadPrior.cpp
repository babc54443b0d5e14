#include "model/PayloadPrior.h"

#include "model/Error.h"
#include "model/PhysicalConsistency.h"

#include <Eigen/Eigenvalues>
#include <QCoreApplication>
#include <cmath>

namespace learnid {

namespace {

struct Text
{
    Q_DECLARE_TR_FUNCTIONS(PayloadPrior)
};

QString vector(const Eigen::Vector3d &v)
{
    return QStringLiteral("(%1, %2, %3)").arg(v.x()).arg(v.y()).arg(v.z());
}

// The distance from c to the bound's edge [m] (negative outside).
double clearance(const PayloadBound &bound, const Eigen::Vector3d &c)
{
    if (!bound.box)
        return bound.radius - (c - bound.centre).norm();
    return std::min((c - bound.lower).minCoeff(), (bound.upper - c).minCoeff());
}

} // namespace

BoundingEllipsoid PayloadBound::ellipsoid() const
{
    if (box)
        return ellipsoidAroundBox(lower, upper);
    BoundingEllipsoid e;
    e.centre = centre;
    e.axes = radius * Eigen::Matrix3d::Identity();
    e.description = describe();
    return e;
}

bool PayloadBound::contains(const Eigen::Vector3d &c) const
{
    return clearance(*this, c) > 0.0;
}

QString PayloadBound::describe() const
{
    if (box)
        return Text::tr("box %1 to %2 m").arg(vector(lower), vector(upper));
    return Text::tr("sphere of radius %1 m around %2 m").arg(radius).arg(vector(centre));
}

InertialParameters PayloadPrior::parameters() const
{
    if (inertiaAtCom)
        return inertialParameters(mass, com, *inertiaAtCom);
    const double size = bound.box ? 0.5 * (bound.upper - bound.lower).minCoeff() : bound.radius;
    const double r = std::min(payloadPriorShare * size, clearance(bound, com) / 3.0);
    // A solid sphere: I = 2/5 m r^2 about each axis.
    return inertialParameters(mass, com, 0.4 * mass * r * r * Eigen::Matrix3d::Identity());
}

void validatePayloadPrior(const PayloadPrior &p, const PayloadFieldNames &names)
{
    if (!std::isfinite(p.mass) || !(p.mass > 0.0))
        throw Error(Text::tr("%1: the payload's mass must be a positive number of kg, not %2")
                        .arg(names.mass)
                        .arg(p.mass));
    if (!p.com.allFinite())
        throw Error(Text::tr("%1: the centre of mass must be finite, not %2")
                        .arg(names.com, vector(p.com)));
    if (p.bound.box) {
        if (!p.bound.lower.allFinite() || !p.bound.upper.allFinite() ||
            !((p.bound.upper - p.bound.lower).minCoeff() > 0.0))
            throw Error(Text::tr("%1: the box's upper corner %2 must lie above its lower "
                                 "corner %3 in x, y and z")
                            .arg(names.box, vector(p.bound.upper), vector(p.bound.lower)));
    } else if (!std::isfinite(p.bound.radius) || !(p.bound.radius > 0.0) ||
               !p.bound.centre.allFinite()) {
        throw Error(Text::tr("%1: the bounding sphere needs a positive radius [m], not %2")
                        .arg(names.radius)
                        .arg(p.bound.radius));
    }
    if (!p.bound.contains(p.com)) {
        throw Error(
            Text::tr("%1: the prior centre of mass %2 m is not inside the bound (%3): "
                     "give a bound that contains it")
                .arg(p.bound.box ? names.box : names.radius, vector(p.com), p.bound.describe()));
    }
    if (p.inertiaAtCom) {
        const Eigen::Matrix3d &i = *p.inertiaAtCom;
        if (!i.allFinite() || (i - i.transpose()).cwiseAbs().maxCoeff() > 1e-12 * i.norm())
            throw Error(
                Text::tr("%1: the inertia must be finite and symmetric").arg(names.inertia));
        const Eigen::Vector3d moments =
            Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(i).eigenvalues();
        if (!(moments[0] > 0.0) || !(moments[0] + moments[1] >= moments[2]))
            throw Error(Text::tr("%1: the inertia is not a real body's (principal moments %2 "
                                 "kg m^2 must be positive and each at most the sum of the others)")
                            .arg(names.inertia, vector(moments)));
        if (!(p.bound.ellipsoid().fitShare(p.parameters()) > 0.0))
            throw Error(Text::tr("%1: a body with this inertia does not fit in the bound (%2)")
                            .arg(names.inertia, p.bound.describe()));
    }
}

Eigen::Matrix3d inertiaFromEntries(const Eigen::Ref<const Eigen::VectorXd> &i)
{
    Eigen::Matrix3d m;
    m << i[0], i[1], i[3], i[1], i[2], i[4], i[3], i[4], i[5];
    return m;
}

PayloadPrior payloadPriorOf(const PayloadSettings &s)
{
    PayloadPrior p;
    p.mass = s.mass;
    p.com = s.com;
    if (s.inertia.size() == 6)
        p.inertiaAtCom = inertiaFromEntries(s.inertia);
    p.bound.radius = s.radius;
    if (s.box.size() == 6) {
        p.bound.box = true;
        p.bound.lower = s.box.head<3>();
        p.bound.upper = s.box.tail<3>();
    }
    return p;
}

InertialParameters simulatedPayloadParameters(const SimulatedPayload &simulated,
                                              const PayloadSettings &settings)
{
    if (simulated.present)
        return inertialParameters(simulated.mass, simulated.com,
                                  inertiaFromEntries(simulated.inertia));
    if (settings.enabled)
        return payloadPriorOf(settings).parameters();
    return InertialParameters::Zero();
}

} // namespace learnid
