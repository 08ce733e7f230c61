// Autosave and crash recovery: while the document has unsaved changes it is written every
// minute to a recovery file in the user's data folder, together with the name of the file
// it belongs to. A normal close or a save removes it; finding it at start-up means the
// last session ended without saving, and the editor offers to recover it.
#pragma once

#include <QDateTime>
#include <QObject>
#include <QPointer>
#include <memory>

class QTimer;

namespace fc::ui {

class Document;

class Autosaver : public QObject {
    Q_OBJECT
public:
    explicit Autosaver(QObject* parent = nullptr);

    void setDocument(Document* document);
    void setInterval(int milliseconds);

    static QString recoveryPath();
    static bool hasRecovery();
    // The recovered document (marked modified, named after its original file), or null.
    static std::unique_ptr<Document> recover(QString* error);
    // The file the recovery belongs to (empty: a plan never saved) and when it was written.
    static QString recoveryOriginalFile();
    static QDateTime recoveryTime();

public slots:
    void saveNow();
    void discard(); // removes the recovery file

private:
    QPointer<Document> document_;
    QTimer* timer_;
};

} // namespace fc::ui
