// Help > Getting Started: a bundled HTML guide (resources/help), in the user's language
// where a translation exists, shown in a text browser that follows its internal links.
#pragma once

#include <QDialog>
#include <QLocale>

class QTextBrowser;

namespace fc::ui {

class HelpDialog : public QDialog {
    Q_OBJECT
public:
    explicit HelpDialog(QWidget* parent = nullptr);

    // ":/help/getting-started_de.html" for German, the English page otherwise.
    static QString pagePath(const QLocale& locale);
    QTextBrowser* browser() const { return browser_; }

private:
    QTextBrowser* browser_;
};

} // namespace fc::ui
