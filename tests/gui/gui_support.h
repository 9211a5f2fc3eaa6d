#pragma once
// Helpers of the studio's GUI tests: screenshots for people to look at, and answering a modal
// dialog as a user would.

#include <QApplication>
#include <QDir>
#include <QDockWidget>
#include <QTest>
#include <QTimer>
#include <QWidget>

#include <functional>
#include <memory>

namespace thespis::test {

// Shows the dock holding `content` and brings it to the front of its tab group.
inline void raiseDock(QWidget* content)
{
    auto* dock = qobject_cast<QDockWidget*>(content->parentWidget());
    QVERIFY(dock);
    dock->show();
    dock->raise();
    QApplication::processEvents();
}

inline void saveScreenshot(QWidget* widget, const QString& name)
{
    QDir().mkpath(QStringLiteral(THESPIS_SCREENSHOT_DIR));
    QVERIFY(widget->grab().save(QStringLiteral(THESPIS_SCREENSHOT_DIR "/") + name));
}

// Runs `act` on the next modal dialog of type T once it is up (a user answering it), then lets
// the caller's exec() return. Fails the test when none comes within 10 s of no dialog.
template <class T>
void whenModal(std::function<void(T*)> act, const QString& screenshot = {})
{
    auto* timer = new QTimer;
    timer->setInterval(50);
    auto tries = std::make_shared<int>(0);
    QObject::connect(timer, &QTimer::timeout, [timer, tries, act, screenshot] {
        if (auto* dialog = qobject_cast<T*>(QApplication::activeModalWidget())) {
            timer->stop();
            timer->deleteLater();
            if (!screenshot.isEmpty())
                saveScreenshot(dialog, screenshot);
            act(dialog);
        } else if (QApplication::activeModalWidget() == nullptr && ++*tries > 200) {
            // Only time without any dialog counts: an earlier dialog may still be up.
            timer->stop();
            timer->deleteLater();
            QFAIL("no dialog came");
        }
    });
    timer->start();
}

} // namespace thespis::test
