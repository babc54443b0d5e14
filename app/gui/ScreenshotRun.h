#pragma once

#include <QObject>
#include <QString>
#include <QStringList>
#include <optional>

namespace learnid {

class MainWindow;
struct ApplyPreview;

/// `learnid --screenshot FILE.png [--screenshot-view VIEW]`: connects the simulated robot, runs
/// the scenario's trials and saves a PNG, then quits the application (exit code 0, or 1 with a
/// message on stderr). The views:
/// - `main` (default): the window after the session, the last estimate accepted and applied;
/// - `apply-dialog`: the confirmation dialog of applying the last estimate (nothing is applied);
/// - `refused-check`: the window after a session with the paper's lambda = 40, whose pre-trial
///   check refuses the second trial;
/// - `recorded-data`: the "Identify from recorded data" dialog after identifying the KUKA LWR4+
///   from its runs 1 + 2, validated on run 3 (the recorded data in the folder LEARNID_DATA);
/// - `payload`: the payload step after its trials, for `--scenario FILE` with a payload section.
class ScreenshotRun : public QObject
{
    Q_OBJECT

public:
    enum class View { Main, ApplyDialog, RefusedCheck, RecordedData, SevenAxis, Payload };

    ScreenshotRun(MainWindow *window, QString path, View view = View::Main);
    void start();

    /// The view of a `--screenshot-view` value, nullopt when unknown.
    static std::optional<View> viewNamed(const QString &name);
    static QStringList viewNames();

private:
    void startRecordedData();
    void startPayload();
    void grabWindowLater();
    bool confirmByScreenshot(const ApplyPreview &preview);
    void finish(const QString &error);

    MainWindow *m_window;
    QString m_path;
    View m_view;
    bool m_started = false;
    bool m_done = false;
};

} // namespace learnid
