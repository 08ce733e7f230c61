#include "window/HelpDialog.h"

#include <QDialogButtonBox>
#include <QFile>
#include <QPushButton>
#include <QTextBrowser>
#include <QVBoxLayout>

namespace fc::ui {

QString HelpDialog::pagePath(const QLocale& locale) {
    const QString translated =
        QStringLiteral(":/help/getting-started_%1.html").arg(locale.name().section('_', 0, 0));
    return QFile::exists(translated) ? translated : QStringLiteral(":/help/getting-started.html");
}

HelpDialog::HelpDialog(QWidget* parent) : QDialog(parent), browser_(new QTextBrowser(this)) {
    setWindowTitle(tr("Getting Started with FloorCover"));
    setObjectName(QStringLiteral("HelpDialog"));
    browser_->setOpenExternalLinks(true);
    browser_->setSource(QUrl(QStringLiteral("qrc") + pagePath(QLocale())));
    browser_->setToolTip(QString());
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    buttons->button(QDialogButtonBox::Close)->setToolTip(tr("Close the guide"));
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(browser_);
    layout->addWidget(buttons);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    resize(720, 640);
}

} // namespace fc::ui
