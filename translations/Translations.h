#pragma once

class QCoreApplication;
class QLocale;

namespace learnid {

/// Installs learnid's translator for `locale` (the .qm files embedded under :/i18n, covering
/// core/, ui/ and app/) and Qt's own qtbase translator (standard dialogs, QCommandLineParser) on
/// `app`, above the English plural forms (`1 log`, `2 logs`; learnid_plurals_en.ts), which every
/// language without a translation uses. Returns whether learnid's translation for the locale was
/// found; English needs none.
bool installTranslators(QCoreApplication &app, const QLocale &locale);

} // namespace learnid
