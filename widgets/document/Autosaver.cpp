#include "document/Autosaver.h"

#include "document/Document.h"
#include "document/DocumentFiles.h"
#include "formats/FileIO.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QSettings>
#include <QStandardPaths>
#include <QTimer>

namespace fc::ui {

namespace {
const char* const kOriginalFileKey = "autosave/originalFile";
}

Autosaver::Autosaver(QObject* parent) : QObject(parent), timer_(new QTimer(this)) {
    timer_->setInterval(60 * 1000);
    connect(timer_, &QTimer::timeout, this, &Autosaver::saveNow);
    timer_->start();
}

void Autosaver::setDocument(Document* document) {
    if (document_)
        disconnect(document_, nullptr, this, nullptr);
    document_ = document;
    if (document_)
        connect(document_, &Document::modifiedChanged, this, [this](bool modified) {
            if (!modified)
                discard(); // saved (or undone to the saved state): nothing to recover
        });
}

void Autosaver::setInterval(int milliseconds) {
    timer_->setInterval(milliseconds);
}

QString Autosaver::recoveryPath() {
    return QStandardPaths::writableLocation(QStandardPaths::AppDataLocation) +
           QStringLiteral("/recovery.fcproj");
}

bool Autosaver::hasRecovery() {
    return QFile::exists(recoveryPath());
}

QString Autosaver::recoveryOriginalFile() {
    return QSettings().value(QLatin1String(kOriginalFileKey)).toString();
}

QDateTime Autosaver::recoveryTime() {
    return QFileInfo(recoveryPath()).lastModified();
}

void Autosaver::saveNow() {
    if (!document_ || !document_->isModified())
        return;
    QDir().mkpath(QStandardPaths::writableLocation(QStandardPaths::AppDataLocation));
    try {
        writeFileAtomically(recoveryPath().toStdString(), writeProject(document_->project()));
        QSettings().setValue(QLatin1String(kOriginalFileKey), document_->fileName());
    } catch (const std::exception&) {
        // A failed autosave must not interrupt editing; the next tick tries again.
    }
}

void Autosaver::discard() {
    QFile::remove(recoveryPath());
    QSettings().remove(QLatin1String(kOriginalFileKey));
}

std::unique_ptr<Document> Autosaver::recover(QString* error) {
    std::unique_ptr<Document> document = loadDocument(recoveryPath(), error);
    if (!document)
        return nullptr;
    document->setFileName(recoveryOriginalFile());
    document->markModified();
    return document;
}

} // namespace fc::ui
