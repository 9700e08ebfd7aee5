#include <QtTest>

#include <QAction>
#include <QDockWidget>
#include <QMenuBar>
#include <QMessageBox>
#include <QPushButton>
#include <QTabWidget>

#include "editor/listing.h"
#include "language.h"
#include "main_window.h"
#include "workspace/workspaces.h"

using k528::studio::MainWindow;

class TestMainWindow : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() {
        QCoreApplication::setOrganizationName("K528StudioTest");
        QSettings().clear();
    }
    void hasTheDockAreas() {
        MainWindow w;
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        for (const char* name : {"dock.k923", "dock.machine", "dock.messages", "dock.axes"}) {
            auto* dock = w.findChild<QDockWidget*>(name);
            QVERIFY2(dock, name);
            QVERIFY(!dock->windowTitle().isEmpty());
        }
        // The operator's workspace: the K923 on the left, the machine's panel
        // on the right, the messages below the program (workspace/).
        QVERIFY(w.workspaces()->activate("operator"));
        QCOMPARE(w.dockWidgetArea(w.k923Dock()), Qt::LeftDockWidgetArea);
        QCOMPARE(w.dockWidgetArea(w.machineDock()), Qt::RightDockWidgetArea);
        QCOMPARE(w.dockWidgetArea(w.messagesDock()), Qt::BottomDockWidgetArea);
        QVERIFY(w.workArea());
    }
    void switchesLanguageAtRunTime() {
        QVERIFY(k528::studio::setLanguage("en"));
        MainWindow w;
        QVERIFY2(w.windowTitle().startsWith(QString("K528 Studio — ")), qPrintable(w.windowTitle()));
        QCOMPARE(w.k923Dock()->windowTitle(), QString("K923 operator panel"));
        QVERIFY(k528::studio::setLanguage("ru"));
        // QApplication posts LanguageChange to every window: let it arrive.
        QTRY_COMPARE(w.k923Dock()->windowTitle(), QString("Панель оператора K923"));
        QCOMPARE(w.menuBar()->actions().first()->text(), QString("&Файл"));
        // Qt's own texts too: the standard buttons of a message box.
        QVERIFY(k528::studio::qtTranslationsLoaded());
        {
            QMessageBox box(QMessageBox::Question, "t", "t", QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel);
            QCOMPARE(box.button(QMessageBox::Cancel)->text(), QString("Отмена"));
            QCOMPARE(box.button(QMessageBox::Save)->text(), QString("Сохранить"));
        }
        // Texts of free functions too (the PDF listing's header).
        {
            const QStringList h = k528::studio::listingHeader({"a.k528", "", QDateTime()}, {}, 1, 1);
            QVERIFY2(h.at(0).startsWith(QString("Файл:")), qPrintable(h.join('|')));
            QVERIFY2(h.at(2).contains(QString("Страница 1 из 1")) || !h.at(2).contains("Page"), qPrintable(h.at(2)));
        }
        QVERIFY(!k528::studio::setLanguage("de"));
        QCOMPARE(k528::studio::currentLanguage(), QString("ru"));
        QVERIFY(k528::studio::setLanguage("en"));
        QTRY_COMPARE(w.k923Dock()->windowTitle(), QString("K923 operator panel"));
        QVERIFY(!k528::studio::qtTranslationsLoaded()); // Qt's English again
        {
            QMessageBox box(QMessageBox::Question, "t", "t", QMessageBox::Cancel);
            QCOMPARE(box.button(QMessageBox::Cancel)->text(), QString("Cancel"));
        }
    }
};

QTEST_MAIN(TestMainWindow)
#include "test_main_window.moc"
