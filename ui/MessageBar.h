#pragma once

#include <QFrame>

class QLabel;
class QToolButton;

namespace learnid {

/// A one-line banner at the top of the window for results and errors that need the
/// technician's attention, without a modal dialog blocking the window.
class MessageBar : public QFrame
{
    Q_OBJECT

public:
    enum class Severity { Info, Success, Error };

    explicit MessageBar(QWidget *parent = nullptr);

    void showMessage(const QString &text, Severity severity);
    QString text() const;
    Severity severity() const { return m_severity; }

private:
    QLabel *m_label;
    QToolButton *m_close;
    Severity m_severity = Severity::Info;
};

} // namespace learnid
