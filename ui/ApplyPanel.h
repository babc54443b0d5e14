#pragma once

#include <QWidget>
#include <optional>

class QAction;
class QLabel;
class QSpinBox;

namespace learnid {

/// Accept / Apply / Revert: which estimate is accepted (default the last), what the robot holds.
class ApplyPanel : public QWidget
{
    Q_OBJECT

public:
    ApplyPanel(QAction *accept, QAction *apply, QAction *revert, QWidget *parent = nullptr);

    /// Estimates 1..count-1 can be accepted; the choice follows the proposed estimate (-1: the
    /// newest; the one that tracked best when a trial tracked worse, TrialSeries.h) unless the
    /// user picked another.
    void setEstimateCount(int count, int proposed = -1);
    int chosenEstimate() const;
    void setChosenEstimate(int k);
    void setAccepted(std::optional<int> k);
    /// One line on what the robot controller holds.
    void setStored(const QString &text);

private:
    QSpinBox *m_estimate;
    QLabel *m_accepted;
    QLabel *m_stored;
    bool m_followProposal = true; ///< the choice follows the proposal until the user picks
    int m_proposed = 0;
};

} // namespace learnid
