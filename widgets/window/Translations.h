// The editor's languages: translations embedded as resources (:/i18n/floorcover_xx.qm),
// chosen by the "language" setting or, when it is empty, by the system's UI languages.
#pragma once

#include <QList>
#include <QLocale>
#include <QPair>
#include <QString>

class QCoreApplication;
class QTranslator;

namespace fc::ui {

// (code, name in that language); the empty code stands for the system's language.
QList<QPair<QString, QString>> availableLanguages();
QString languageSetting();
void setLanguageSetting(const QString& code);

// Loads the editor's translation for `locale` into `translator`; false for English (the
// source language) or a language without a translation.
bool loadEditorTranslation(QTranslator& translator, const QLocale& locale);
// Qt's own strings (standard buttons, file dialogs) for the locale, from the system's Qt
// translations (Debian: qt6-translations-l10n, installed by scripts/install-deps.sh).
bool loadQtTranslation(QTranslator& translator, const QLocale& locale);
// Installs the editor's and Qt's own translations for the chosen language.
void installTranslations(QCoreApplication& application);

} // namespace fc::ui
