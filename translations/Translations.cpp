#include "translations/Translations.h"

#include <QCoreApplication>
#include <QLibraryInfo>
#include <QLocale>
#include <QTranslator>

namespace learnid {

bool installTranslators(QCoreApplication &app, const QLocale &locale)
{
    // Searched last (translators are searched in the reverse order of installation): the
    // English plural forms, for English and any language learnid has no translation for.
    auto *plurals = new QTranslator(&app);
    if (plurals->load(QStringLiteral(":/i18n/learnid_plurals_en.qm")))
        QCoreApplication::installTranslator(plurals);
    else
        delete plurals;
    auto *own = new QTranslator(&app);
    const bool found =
        own->load(locale, QStringLiteral("learnid"), QStringLiteral("_"), QStringLiteral(":/i18n"));
    if (found)
        QCoreApplication::installTranslator(own);
    else
        delete own;
    auto *qt = new QTranslator(&app);
    if (qt->load(locale, QStringLiteral("qtbase"), QStringLiteral("_"),
                 QLibraryInfo::path(QLibraryInfo::TranslationsPath)))
        QCoreApplication::installTranslator(qt);
    else
        delete qt;
    return found;
}

} // namespace learnid
