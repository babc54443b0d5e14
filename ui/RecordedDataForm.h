#pragma once

#include "service/LogIdentification.h"

#include <QWidget>
#include <functional>
#include <optional>

class QCheckBox;
class QComboBox;
class QLineEdit;
class QListWidget;
class QPushButton;

namespace learnid {

/// The files the "Recorded data" window asks the technician for.
enum class RecordedDataPath {
    RobotUrdf,      ///< open one URDF
    TrainingLogs,   ///< open logs (several)
    ValidationLogs, ///< open logs (several)
    GainsScenario,  ///< open one scenario file
    ParameterFile,  ///< save the parameter file (JSON)
    IdentifiedUrdf, ///< save the identified URDF
};
/// Asks for paths (empty: cancelled); suggested is a folder or a file in it. The default shows
/// file dialogs (chooseRecordedDataPaths); tests inject their own.
using RecordedDataPathChooser =
    std::function<QStringList(RecordedDataPath purpose, const QString &suggested)>;

/// The QFileDialog of each purpose.
QStringList chooseRecordedDataPaths(QWidget *parent, RecordedDataPath purpose,
                                    const QString &suggested);

/// What to identify from recorded logs: the robot (a built-in URDF robot or a URDF file), the
/// training and validation logs, the logs' columns in `--columns` syntax, the joint terms to
/// fit, and the scenario whose controller gains the parameter file records (optional).
class RecordedDataForm : public QWidget
{
    Q_OBJECT

public:
    explicit RecordedDataForm(QWidget *parent = nullptr);

    void setPathChooser(RecordedDataPathChooser chooser) { m_chooser = std::move(chooser); }
    /// The folder file choices start in (the last one used is remembered by the caller).
    void setStartDirectory(const QString &dir) { m_startDir = dir; }

    /// A built-in robot id, or else a URDF file's path.
    void setRobot(const QString &robot);
    void setTrainingLogs(const QStringList &paths);
    void setValidationLogs(const QStringList &paths);
    void setColumns(const QString &spec);
    void setGainsScenario(const QString &path);
    QStringList trainingLogs() const;
    QStringList validationLogs() const;
    QString gainsScenario() const;
    void setEditable(bool editable);

    /// The request of the form, or nullopt with error saying what is missing or wrong (the
    /// columns as parseLogColumns() says).
    std::optional<LogIdentificationRequest> request(QString *error) const;

signals:
    /// A folder the technician chose a file in.
    void directoryUsed(const QString &dir);

private:
    QStringList choose(RecordedDataPath purpose);
    QWidget *logList(QListWidget *list, RecordedDataPath purpose, const char *addName,
                     const char *removeName);
    void updateUrdfField();

    QComboBox *m_robot;
    QLineEdit *m_urdf;
    QPushButton *m_browseUrdf;
    QListWidget *m_training;
    QListWidget *m_validation;
    QLineEdit *m_columns;
    QList<QCheckBox *> m_terms; ///< armature, viscous, Coulomb, offset
    QLineEdit *m_gains;
    QPushButton *m_browseGains;
    RecordedDataPathChooser m_chooser;
    QString m_startDir;
};

} // namespace learnid
