// Preferences: the user interface language (applied at the next start).
#pragma once

#include <QDialog>

class QComboBox;

namespace fc::ui {

class PreferencesDialog : public QDialog {
    Q_OBJECT
public:
    explicit PreferencesDialog(QWidget* parent = nullptr);

    QComboBox* languageBox() const { return language_; }
    void accept() override; // stores the choice

private:
    QComboBox* language_;
};

} // namespace fc::ui
