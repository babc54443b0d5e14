#include "io/LoopHistory.h"

#include "io/JsonReader.h"
#include "io/JsonTree.h"
#include "io/ValueChecks.h"
#include "model/Error.h"

#include <QCoreApplication>
#include <QRegularExpression>

namespace learnid {

namespace {

struct Text
{
    Q_DECLARE_TR_FUNCTIONS(LoopHistory)
};

QString key(const char *name)
{
    return QString::fromLatin1(name);
}

constexpr int maxJoints = 64;
constexpr int maxParameters = 10000;

// A file of the folder itself: no path, no hidden file, no "..".
void checkFileName(const QString &path, const QString &name)
{
    static const QRegularExpression plain(QStringLiteral("^[A-Za-z0-9][A-Za-z0-9._-]{0,99}$"));
    if (!plain.match(name).hasMatch() || name.contains(QLatin1String("..")))
        throwAtKey(path, Text::tr("must be a plain file name in the history folder (letters, "
                                  "digits, '.', '_', '-'), got \"%1\"")
                             .arg(name.left(100)));
}

void checkPlanId(const QString &path, const QString &id)
{
    static const QRegularExpression hex(QStringLiteral("^[0-9a-f]{64}$"));
    if (!hex.match(id).hasMatch())
        throwAtKey(
            path,
            Text::tr("must be 64 lower-case hex digits (SHA-256), got \"%1\"").arg(id.left(100)));
}

void checkHistory(const LoopHistory &h)
{
    checkIntegerRange(key("robot.joints"), h.joints, 1, maxJoints);
    checkIntegerRange(key("robot.parameters"), h.parameters, 1, maxParameters);
    if (h.robotModel.isEmpty())
        throwAtKey(key("robot.model"), Text::tr("must not be empty"));
    if (h.law.isEmpty())
        throwAtKey(key("law"), Text::tr("must not be empty"));
    checkLength(key("estimates"), h.estimates.size(), h.trials.size() + 1,
                Text::tr("one more than trials, the initial estimate first"));
    for (int k = 0; k < int(h.estimates.size()); ++k)
        checkFileName(jsonIndexPath(key("estimates"), k), h.estimates.at(k));
    const QString perJoint = Text::tr("one per joint");
    for (int k = 0; k < int(h.trials.size()); ++k) {
        const LoopHistory::Trial &t = h.trials.at(k);
        const QString path = jsonIndexPath(key("trials"), k);
        checkPlanId(jsonKeyPath(path, key("planId")), t.planId);
        checkFileName(jsonKeyPath(path, key("plan")), t.plan);
        if (t.logs.isEmpty())
            throwAtKey(jsonKeyPath(path, key("logs")), Text::tr("must name at least one log"));
        for (int r = 0; r < int(t.logs.size()); ++r)
            checkFileName(jsonIndexPath(jsonKeyPath(path, key("logs")), r), t.logs.at(r));
        checkVector(jsonKeyPath(path, key("maxTrackingErrorDeg")), t.maxTrackingErrorDeg, h.joints,
                    perJoint, EntryRule::NonNegative);
        checkVector(jsonKeyPath(path, key("rmsTrackingErrorDeg")), t.rmsTrackingErrorDeg, h.joints,
                    perJoint, EntryRule::NonNegative);
    }
    for (int i = 0; i < int(h.pendingPlans.size()); ++i) {
        const QString path = jsonIndexPath(key("pendingPlans"), i);
        checkPlanId(jsonKeyPath(path, key("planId")), h.pendingPlans.at(i).planId);
        checkFileName(jsonKeyPath(path, key("plan")), h.pendingPlans.at(i).plan);
    }
}

JsonTree names(const QStringList &list)
{
    JsonTree a = JsonTree::array();
    for (const QString &s : list)
        a.append(s);
    return a;
}

QStringList readNames(const QJsonValue &value, const QString &path)
{
    QStringList out;
    const QJsonArray array = jsonArray(value, path);
    for (int i = 0; i < int(array.size()); ++i)
        out << jsonString(array.at(i), jsonIndexPath(path, i));
    return out;
}

LoopHistory readHistory(const QJsonObject &root)
{
    JsonObjectReader r(root, QString());
    const QJsonValue schema = r.value(key("schema"));
    if (schema.isUndefined())
        throwAtKey(key("schema"), Text::tr("is missing; this is not a learnid history index"));
    if (jsonString(schema, key("schema")) != QLatin1String(loopHistorySchema))
        throwAtKey(key("schema"),
                   Text::tr("this version of learnid reads \"%1\", got %2")
                       .arg(QLatin1String(loopHistorySchema), describeJsonValue(schema)));
    LoopHistory h;
    JsonObjectReader robot = r.object(key("robot"));
    h.robotModel = jsonString(robot.require(key("model")), robot.keyPath(key("model")));
    h.joints =
        int(jsonInteger(robot.require(key("joints")), robot.keyPath(key("joints")), 1, maxJoints));
    h.parameters = int(jsonInteger(robot.require(key("parameters")),
                                   robot.keyPath(key("parameters")), 1, maxParameters));
    robot.rejectUnknownKeys();
    h.law = jsonString(r.require(key("law")), key("law"));
    if (std::optional<JsonObjectReader> payload = r.optionalObject(key("payload"))) {
        h.payloadLink = jsonString(payload->require(key("link")), payload->keyPath(key("link")));
        if (h.payloadLink.isEmpty())
            throwAtKey(payload->keyPath(key("link")), Text::tr("must not be empty"));
        payload->rejectUnknownKeys();
    }
    h.estimates = readNames(r.require(key("estimates")), key("estimates"));
    const QJsonArray trials = jsonArray(r.require(key("trials")), key("trials"));
    for (int k = 0; k < int(trials.size()); ++k) {
        JsonObjectReader t(trials.at(k), jsonIndexPath(key("trials"), k));
        LoopHistory::Trial trial;
        trial.planId = jsonString(t.require(key("planId")), t.keyPath(key("planId")));
        trial.plan = jsonString(t.require(key("plan")), t.keyPath(key("plan")));
        trial.logs = readNames(t.require(key("logs")), t.keyPath(key("logs")));
        trial.maxTrackingErrorDeg = jsonNumbers(t.require(key("maxTrackingErrorDeg")),
                                                t.keyPath(key("maxTrackingErrorDeg")));
        trial.rmsTrackingErrorDeg = jsonNumbers(t.require(key("rmsTrackingErrorDeg")),
                                                t.keyPath(key("rmsTrackingErrorDeg")));
        t.rejectUnknownKeys();
        h.trials << trial;
    }
    const QJsonArray pending = jsonArray(r.require(key("pendingPlans")), key("pendingPlans"));
    for (int i = 0; i < int(pending.size()); ++i) {
        JsonObjectReader p(pending.at(i), jsonIndexPath(key("pendingPlans"), i));
        LoopHistory::PendingPlan plan;
        plan.planId = jsonString(p.require(key("planId")), p.keyPath(key("planId")));
        plan.plan = jsonString(p.require(key("plan")), p.keyPath(key("plan")));
        p.rejectUnknownKeys();
        h.pendingPlans << plan;
    }
    r.rejectUnknownKeys();
    checkHistory(h);
    return h;
}

} // namespace

QByteArray loopHistoryToJson(const LoopHistory &h)
{
    checkHistory(h);
    JsonTree robot = JsonTree::object();
    robot.insert(key("model"), h.robotModel)
        .insert(key("joints"), h.joints)
        .insert(key("parameters"), h.parameters);
    JsonTree trials = JsonTree::array();
    for (const LoopHistory::Trial &t : h.trials) {
        JsonTree trial = JsonTree::object();
        trial.insert(key("planId"), t.planId)
            .insert(key("plan"), t.plan)
            .insert(key("logs"), names(t.logs))
            .insert(key("maxTrackingErrorDeg"), JsonTree::numbers(t.maxTrackingErrorDeg))
            .insert(key("rmsTrackingErrorDeg"), JsonTree::numbers(t.rmsTrackingErrorDeg));
        trials.append(trial);
    }
    JsonTree pending = JsonTree::array();
    for (const LoopHistory::PendingPlan &p : h.pendingPlans) {
        JsonTree plan = JsonTree::object();
        plan.insert(key("planId"), p.planId).insert(key("plan"), p.plan);
        pending.append(plan);
    }
    JsonTree root = JsonTree::object();
    root.insert(key("schema"), QString::fromLatin1(loopHistorySchema))
        .insert(key("robot"), robot)
        .insert(key("law"), h.law);
    if (!h.payloadLink.isEmpty()) {
        JsonTree payload = JsonTree::object();
        payload.insert(key("link"), h.payloadLink);
        root.insert(key("payload"), payload);
    }
    root.insert(key("estimates"), names(h.estimates))
        .insert(key("trials"), trials)
        .insert(key("pendingPlans"), pending);
    return root.toJson();
}

LoopHistory loopHistoryFromJson(const QByteArray &json, const QString &source)
{
    const QJsonObject root = parseJsonObject(json, source);
    try {
        return readHistory(root);
    } catch (const Error &e) {
        throw Error(Text::tr("%1: %2").arg(source, e.message()));
    }
}

} // namespace learnid
