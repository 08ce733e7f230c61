// Spin boxes and combo boxes take the mouse wheel only once they have focus (clicked or
// tabbed into). Scrolling a panel over them otherwise changes whatever passes under the
// pointer: a supervisor scrolling the Planning panel set the turn time to 0.0 s this way.
// Unfocused, the wheel scrolls the panel instead.
#pragma once

#include <QObject>

namespace fc::ui {

class WheelGuard : public QObject {
    Q_OBJECT
public:
    // Installs one guard on the application (idempotent).
    static void install();

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    using QObject::QObject;
};

} // namespace fc::ui
