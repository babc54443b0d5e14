#include "model/ModelFactory.h"

#include "model/TwoLinkArm.h"

namespace learnid {

QStringList knownRobotModels()
{
    return {QStringLiteral("paper-2link")};
}

std::shared_ptr<const RobotModel> makeRobotModel(const QString &id)
{
    if (id == QLatin1String("paper-2link"))
        return std::make_shared<TwoLinkArm>();
    return nullptr;
}

} // namespace learnid
