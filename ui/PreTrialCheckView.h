#pragma once

#include "session/TrialResult.h"

#include <QWidget>

class QLabel;
class QTableWidget;

namespace learnid {

/// The pre-trial check of the next trial, shown before any motion: planned duration, peak
/// torque per joint against its limit, the closed-loop stability verdict, and the reason when
/// the trial is refused.
class PreTrialCheckView : public QWidget
{
    Q_OBJECT

public:
    explicit PreTrialCheckView(QWidget *parent = nullptr);

    void setCheck(const PreTrialCheck &check, int nextTrial);
    void clear(const QString &why);
    /// The verdict line as shown, e.g. "Refused: ...".
    QString verdictText() const;

private:
    QLabel *m_verdict;
    QLabel *m_duration;
    QLabel *m_stability;
    QTableWidget *m_torques;
};

} // namespace learnid
