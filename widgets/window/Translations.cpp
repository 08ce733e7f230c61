#include "window/Translations.h"

#include <QCoreApplication>
#include <QLibraryInfo>
#include <QSettings>
#include <QTranslator>

namespace fc::ui {

namespace {
const char* const kLanguageKey = "language";
}

QList<QPair<QString, QString>> availableLanguages() {
    return {
        {QString(), QCoreApplication::translate("fc::ui::Translations", "System language")},
        {QStringLiteral("en"), QStringLiteral("English")},
        {QStringLiteral("de"), QStringLiteral("Deutsch")},
        {QStringLiteral("fr"), QStringLiteral("Français")},
    };
}

QString languageSetting() {
    return QSettings().value(QLatin1String(kLanguageKey)).toString();
}

void setLanguageSetting(const QString& code) {
    QSettings().setValue(QLatin1String(kLanguageKey), code);
}

bool loadEditorTranslation(QTranslator& translator, const QLocale& locale) {
    return translator.load(locale, QStringLiteral("floorcover"), QStringLiteral("_"),
                           QStringLiteral(":/i18n"));
}

bool loadQtTranslation(QTranslator& translator, const QLocale& locale) {
    return translator.load(locale, QStringLiteral("qtbase"), QStringLiteral("_"),
                           QLibraryInfo::path(QLibraryInfo::TranslationsPath));
}

void installTranslations(QCoreApplication& application) {
    const QString code = languageSetting();
    const QLocale locale = code.isEmpty() ? QLocale::system() : QLocale(code);
    if (!code.isEmpty())
        QLocale::setDefault(locale); // numbers and dates follow the chosen language too
    auto* editor = new QTranslator(&application);
    if (loadEditorTranslation(*editor, locale))
        QCoreApplication::installTranslator(editor);
    // Qt's own strings (standard buttons and dialogs), from the system's Qt translations.
    auto* qt = new QTranslator(&application);
    if (loadQtTranslation(*qt, locale))
        QCoreApplication::installTranslator(qt);
}

} // namespace fc::ui
