#include "dialogs/PreferencesDialog.h"

#include "window/Translations.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QLabel>

namespace fc::ui {

PreferencesDialog::PreferencesDialog(QWidget* parent) : QDialog(parent) {
    setWindowTitle(tr("Preferences"));
    language_ = new QComboBox;
    for (const auto& [code, name] : availableLanguages())
        language_->addItem(name, code);
    language_->setCurrentIndex(std::max(0, language_->findData(languageSetting())));
    language_->setToolTip(tr("The language of the editor, its messages and Qt's dialogs"));
    auto* note = new QLabel(tr("The language changes at the next start of FloorCover."));
    note->setWordWrap(true);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto* form = new QFormLayout(this);
    form->addRow(tr("Language"), language_);
    form->addRow(note);
    form->addRow(buttons);
}

void PreferencesDialog::accept() {
    setLanguageSetting(language_->currentData().toString());
    QDialog::accept();
}

} // namespace fc::ui
