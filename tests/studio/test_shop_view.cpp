// The Shop workspace (studio.shop_view) with real parts: sixteen `k528 serve
// --tcp` on free localhost ports registered as machines of a test database
// (their `line` set with `k528 db set`); the workspace shows a tile per
// machine with its mode; a server killed is shown offline within a second
// and back when it serves again; a click on a tile makes that machine's
// controller the one every view shows; the Controller dock offers the
// database's machines and connects over Modbus TCP; the poller runs only
// while the page is shown.
#include "cli_runner.h"
#include "controller/controller_dock.h"
#include "controller/link_controller.h"
#include "controller/simulated_controller.h"
#include "language.h"
#include "main_window.h"
#include "rig/mqtt_broker.h"
#include "rig/shop_machines.h"
#include "rig/widgets.h"
#include "session/machine_source.h"
#include "shop/shop_view.h"
#include "test_util.h"
#include "workspace/workspaces.h"

#include <QApplication>
#include <QBarCategoryAxis>
#include <QChart>
#include <QChartView>
#include <QProcessEnvironment>
#include <QScrollArea>
#include <QSysInfo>
#include "db/state_times.h"
#include "shop/state_time.h"
#include <QComboBox>
#include <QDir>
#include <QElapsedTimer>
#include <QCheckBox>
#include <QLabel>
#include <QLineEdit>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTcpSocket>
#include <QTemporaryDir>
#include <QTreeWidget>
#include <QtTest>
#include <memory>

using namespace k528;
using namespace k528::studio;
using namespace k528::testrig;

namespace {

const QString kCli = QStringLiteral(K528_CLI);
constexpr int kMachines = 16; // a shop's row of machines: the page must hold them all

} // namespace

class TestShopView : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;
    ShopMachines shop_;

    // m01 in F7 «РАБОТА С ПЭВМ», the others in F2 (after power-on).
    QStringList keysOf(int i) const { return i == 0 ? QStringList{"--keys", kWorkWithPcKeys} : QStringList{}; }

private slots:
    void initTestCase() {
        QCoreApplication::setOrganizationName("K528StudioTest");
        QSettings().clear();
        QVERIFY(setLanguage("en"));
        QVERIFY(dir_.isValid());
        qputenv("K528_DB", dir_.filePath("shop.db").toUtf8());
        qputenv("K528_PLUGIN_PATH", QFileInfo(QStringLiteral(K528_TCP_PLUGIN)).absolutePath().toUtf8());
        const QString failed = shop_.start(kCli, QDir(dir_.path()), shopMachineNames(kMachines),
                                           [this](int i) { return keysOf(i); });
        QVERIFY2(failed.isEmpty(), qPrintable(failed));
    }
    void cleanupTestCase() { shop_.stop(); }

    // A tile per machine with its mode; the poller runs only while shown.
    void tilesShowEveryMachine() {
        MainWindow w(loadMachine("training-lathe"));
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        ShopView* shop = w.shopView();
        QVERIFY(shop);
        QVERIFY(w.workspaces()->activate("technologist"));
        QApplication::processEvents();
        QVERIFY(!shop->polling());
        QVERIFY(w.workspaces()->activate("shop"));
        QTRY_VERIFY(shop->isVisible());
        QVERIFY(shop->polling());
        QCOMPARE(static_cast<int>(shop->tiles().size()), kMachines);
        for (int i = 0; i < kMachines; ++i) {
            ShopTile* t = shop->tile(shopMachineName(i));
            QVERIFY(t);
            QTRY_VERIFY_WITH_TIMEOUT(shop->state(shopMachineName(i))->online, 10000);
        }
        QTRY_VERIFY_WITH_TIMEOUT(shop->tile("m01")->modeText().contains("F7"), 5000);
        QVERIFY(shop->tile("m01")->modeText().contains("РАБОТА С ПЭВМ"));
        QVERIFY2(shop->tile("m02")->modeText().contains("F2"), qPrintable(shop->tile("m02")->modeText()));
        QCOMPARE(shop->tile("m02")->stateText(), QString("idle"));
        // Another workspace: the poller stops.
        QVERIFY(w.workspaces()->activate("operator"));
        QApplication::processEvents();
        QVERIFY(!shop->polling());
        QVERIFY(w.workspaces()->activate("shop"));
        QTRY_VERIFY(shop->polling());
    }

    // A server killed: offline within a second; back when it serves again.
    void offlineWithinASecondAndBack() {
        MainWindow w(loadMachine("training-lathe"));
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QVERIFY(w.workspaces()->activate("shop"));
        ShopView* shop = w.shopView();
        QTRY_VERIFY_WITH_TIMEOUT(shop->state("m02") && shop->state("m02")->online, 10000);
        QElapsedTimer t;
        shop_.serves[1]->kill();
        t.start();
        QTRY_VERIFY_WITH_TIMEOUT(!shop->state("m02")->online, 5000);
        const qint64 ms = t.elapsed();
        qInfo("offline shown %lld ms after the kill", static_cast<long long>(ms));
        QVERIFY2(ms <= 1000, qPrintable(QString::number(ms)));
        QCOMPARE(shop->tile("m02")->stateText(), QString("offline"));
        // Why, in the window's language: the link's ids through tr().
        const QString whyEn = shop->tile("m02")->offlineReason();
        QVERIFY2(!whyEn.isEmpty() && whyEn == QString::fromStdString(shop->state("m02")->why), qPrintable(whyEn));
        QVERIFY(setLanguage("ru"));
        QApplication::processEvents();
        const QString whyRu = shop->tile("m02")->offlineReason();
        static const QRegularExpression english(QStringLiteral("(?:[A-Za-z]+ ){2,}[A-Za-z]+"));
        QVERIFY2(!whyRu.isEmpty() && whyRu != whyEn && !whyRu.contains(english), qPrintable(whyRu));
        qInfo("offline: «%s» / «%s»", qPrintable(whyEn), qPrintable(whyRu));
        QVERIFY(setLanguage("en"));
        QApplication::processEvents();
        QVERIFY(shop->state("m01")->online); // the others go on
        QByteArray said;
        QVERIFY2(shop_.serves[1]->start({}, &said), said.constData());
        t.restart();
        QTRY_VERIFY_WITH_TIMEOUT(shop->state("m02")->online, 5000);
        qInfo("online again %lld ms after the server said it serves", static_cast<long long>(t.elapsed()));
        QVERIFY(shop->tile("m02")->modeText().contains("F2"));
        QVERIFY(shop->today("m02")[3] > 0); // some offline time today
        K528_VERIFY_SHOT(w.grab(), QStringLiteral("shop_view.png"));
    }

    // A click on a tile: that machine's controller on every view.
    void clickShowsTheMachinesController() {
        MainWindow w(loadMachine("training-lathe"));
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QVERIFY(w.workspaces()->activate("shop"));
        ShopView* shop = w.shopView();
        QVERIFY(w.viewedController() == w.simulatedController());
        auto* dock = w.findChild<ControllerDock*>("dock.controller");
        QVERIFY(dock);
        // Connect offers the database's machines with their lines.
        QCOMPARE(dock->machineBox()->count(), kMachines + 1);
        QVERIFY(dock->machineBox()->itemText(1).contains(QString::number(shop_.ports[0])));
        for (int i : {2, 0}) {
            const QString name = shopMachineName(i);
            QTRY_VERIFY(shop->tile(name)->isVisible());
            QTest::mouseClick(shop->tile(name), Qt::LeftButton, {}, QPoint(20, 20));
            QTRY_VERIFY_WITH_TIMEOUT(dock->link() && dock->link()->isOpen() &&
                                         w.viewedController() == dock->link(),
                                     10000);
            QVERIFY2(dock->link()->where().contains(QString::number(shop_.ports[static_cast<std::size_t>(i)])),
                     qPrintable(dock->link()->where()));
            QCOMPARE(dock->connectedMachine(), name);
            QVERIFY(dock->link()->description().contains("Modbus TCP"));
            QTRY_COMPARE_WITH_TIMEOUT(w.viewedController()->state().mode, i == 0 ? 7 : 2, 5000);
        }
        QTRY_VERIFY_WITH_TIMEOUT(dock->monitorLabel()->text().contains("F7"), 5000);
        K528_VERIFY_SHOT(w.grab(), QStringLiteral("shop_clicked.png"));
    }

    // Sixteen machines on a shop PC's screen and an office's, in Russian and
    // English: a tile each, every one reachable (the tiles scroll when they
    // do not fit), each one online with its mode; the chart has a bar each.
    // K528_TEST_SCREENSHOTS=DIR saves each window.
    void sixteenTilesAtShopSizes() {
        const QByteArray shots = qgetenv("K528_TEST_SCREENSHOTS");
        for (const QSize size : {QSize(1366, 768), QSize(1920, 1080)})
            for (const char* lang : {"ru", "en"}) {
                QVERIFY(setLanguage(lang));
                MainWindow w(loadMachine("training-lathe"));
                w.resize(size);
                w.show();
                QVERIFY(QTest::qWaitForWindowExposed(&w));
                QVERIFY(w.workspaces()->activate("shop"));
                ShopView* shop = w.shopView();
                QCOMPARE(static_cast<int>(shop->tiles().size()), kMachines);
                for (int i = 0; i < kMachines; ++i)
                    QTRY_VERIFY_WITH_TIMEOUT(shop->state(shopMachineName(i)) && shop->state(shopMachineName(i))->online,
                                             10000);
                QTRY_VERIFY_WITH_TIMEOUT(shop->tile("m16")->modeText().contains("F2"), 5000);
                auto* scroll = shop->findChild<QScrollArea*>("shop.tiles");
                QVERIFY(scroll);
                QVERIFY2(scroll->viewport()->height() >= 150,
                         qPrintable(QString("%1x%2 %3: tiles %4 px high")
                                        .arg(size.width()).arg(size.height()).arg(lang)
                                        .arg(scroll->viewport()->height())));
                int seen = 0;
                for (int i = 0; i < kMachines; ++i) {
                    ShopTile* t = shop->tile(shopMachineName(i));
                    scroll->ensureWidgetVisible(t, 0, 0);
                    QApplication::processEvents();
                    // Whole in the viewport once scrolled to, as wide as it asks.
                    const QRect r(t->mapTo(scroll->viewport(), QPoint(0, 0)), t->size());
                    QVERIFY2(scroll->viewport()->rect().contains(r),
                             qPrintable(QStringLiteral("%1 at %2x%3 %4").arg(shopMachineName(i)).arg(size.width())
                                            .arg(size.height()).arg(lang)));
                    QVERIFY(t->width() >= t->minimumSizeHint().width());
                    // Each of its texts whole: a line that does not wrap as
                    // wide as its text, one that wraps as tall as its lines.
                    for (const QLabel* l : t->findChildren<QLabel*>()) {
                        if (!l->isVisible() || l->text().isEmpty())
                            continue;
                        const bool whole = l->wordWrap() ? l->height() >= l->heightForWidth(l->width())
                                                         : l->width() >= l->sizeHint().width();
                        QVERIFY2(whole && t->rect().contains(QRect(l->mapTo(t, QPoint(0, 0)), l->size())),
                                 qPrintable(QStringLiteral("%1 %2 «%3» %4x%5 (needs %6x%7) at %8x%9 %10")
                                                .arg(shopMachineName(i), l->objectName(), l->text())
                                                .arg(l->width())
                                                .arg(l->height())
                                                .arg(l->sizeHint().width())
                                                .arg(l->wordWrap() ? l->heightForWidth(l->width()) : l->sizeHint().height())
                                                .arg(size.width())
                                                .arg(size.height())
                                                .arg(lang)));
                    }
                    ++seen;
                }
                QCOMPARE(seen, kMachines);
                // The chart reads top-down as the tiles do: m01 at the top
                // (a horizontal bar chart's last category), m16 at the bottom.
                auto* axis = qobject_cast<QBarCategoryAxis*>(shop->chartView()->chart()->axes(Qt::Vertical).value(0));
                QVERIFY(axis);
                QCOMPARE(axis->categories().size(), kMachines);
                QCOMPARE(axis->categories().constLast(), shopMachineName(0));
                QCOMPARE(axis->categories().constFirst(), shopMachineName(kMachines - 1));
                scroll->ensureWidgetVisible(shop->tile("m01"), 0, 0);
                QApplication::processEvents();
                if (!shots.isEmpty()) {
                    QDir().mkpath(QString::fromLocal8Bit(shots));
                    K528_VERIFY_SHOT(w.grab(), QStringLiteral("shop16_%1x%2_%3.png")
                                                   .arg(size.width())
                                                   .arg(size.height())
                                                   .arg(lang));
                }
            }
        QVERIFY(setLanguage("en"));
    }

    // The day's time in each state is the database's: a studio (another
    // process, the real k528studio in --screenshot mode) polls the machines
    // for a few seconds and quits; its time is in state_times (this PC's
    // studio as the source), and a window opened afterwards (a restarted
    // studio) starts its chart from it. With a broker, that studio published
    // and its quitting said the goodbye (retained "stopped"), not the will.
    void timeInStateSurvivesARestart() {
        const QString today = QDate::currentDate().toString(Qt::ISODate);
        const std::string source = "studio@" + QSysInfo::machineHostName().toStdString();
        std::int64_t before = 0;
        {
            db::Database d = db::Database::open(db::Location::parse(shop_.db.toStdString()));
            for (const db::StateTime& r : db::stateTimes(d, today.toStdString(), source))
                if (r.machine == "m03")
                    before += r.ms;
        }
        QTemporaryDir config;
        QVERIFY(config.isValid());
        MqttBroker broker;
        const bool mqtt = mosquittoInstalled();
        {
            QSettings settings(config.filePath("K528Studio/k528studio.conf"), QSettings::IniFormat);
            if (mqtt) {
                QVERIFY(broker.start(freePorts(1).at(0)));
                settings.setValue("shop/broker", broker.url());
                settings.setValue("shop/publish", true);
            }
        }
        QProcess studio;
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.insert("XDG_CONFIG_HOME", config.path());
        env.insert("K528_DB", shop_.db);
        studio.setProcessEnvironment(env);
        studio.start(QStringLiteral(K528_STUDIO), {"--lang", "en", "--workspace", "shop", "--screenshot",
                                                   config.filePath("shot.png"), "--screenshot-delay", "5000"});
        QVERIFY(studio.waitForStarted());
        QVERIFY(studio.waitForFinished(60000));
        QVERIFY2(studio.exitCode() == 0, studio.readAllStandardError().constData());
        std::int64_t after = 0;
        {
            db::Database d = db::Database::open(db::Location::parse(shop_.db.toStdString()));
            int machines = 0;
            for (const db::StateTime& r : db::stateTimes(d, today.toStdString(), source)) {
                if (r.machine == "m03")
                    after += r.ms;
                machines += r.state == "idle" ? 1 : 0;
            }
            QCOMPARE(machines, kMachines);
        }
        qInfo("m03: %lld ms of today on record after the other studio's run (%lld before)",
              static_cast<long long>(after), static_cast<long long>(before));
        QVERIFY2(after - before >= 2000, qPrintable(QString::number(after - before)));
        // A window opened now (the restarted studio) starts from the record.
        {
            MainWindow w(loadMachine("training-lathe"));
            ShopView* shop = w.shopView();
            std::int64_t shown = 0;
            for (const std::int64_t ms : shop->today("m03"))
                shown += ms;
            QVERIFY2(shown >= after, qPrintable(QStringLiteral("%1 < %2").arg(shown).arg(after)));
        }
        if (mqtt) {
            QProcess sub;
            broker.subscribe(sub, "k528/_publisher/#", 1, 10);
            QVERIFY(sub.waitForFinished(15000));
            const QString bye = QString::fromUtf8(sub.readAllStandardOutput());
            QVERIFY2(bye.contains("\"online\":false") && bye.contains("\"why\":\"stopped\"") &&
                         !bye.contains("last will"),
                     qPrintable(bye));
            broker.subscribe(sub, "k528/+/state", kMachines, 10);
            QVERIFY(sub.waitForFinished(15000));
            QCOMPARE(QString::fromUtf8(sub.readAllStandardOutput()).count("/state {"), kMachines);
        }
    }

    // A broker's address that is not one is refused in the window's language
    // (core's mqtt.url-* texts through the window's translations).
    void badBrokerInTheWindowsLanguage() {
#ifndef K528_STUDIO_MQTT
        QSKIP("built without MQTT");
#endif
        QVERIFY(setLanguage("ru"));
        {
            MainWindow w(loadMachine("training-lathe"));
            w.show();
            QVERIFY(QTest::qWaitForWindowExposed(&w));
            QVERIFY(w.workspaces()->activate("shop"));
            ShopView* shop = w.shopView();
            auto* state = shop->findChild<QLabel*>("shop.publishState");
            QVERIFY(state);
            shop->brokerBox()->setText("http://127.0.0.1:1883");
            shop->publishBox()->setChecked(true);
            QVERIFY(!shop->publishing());
            QCOMPARE(state->toolTip(), QStringLiteral("«http://127.0.0.1:1883» — не mqtt://ХОСТ[:ПОРТ] (MQTT без "
                                                      "шифрования; TLS не поддерживается)"));
            shop->brokerBox()->setText("mqtt://127.0.0.1:99999");
            shop->publishBox()->setChecked(true);
            QCOMPARE(state->toolTip(), QStringLiteral("«mqtt://127.0.0.1:99999»: порт — 1..65535"));
        }
        QVERIFY(setLanguage("en"));
    }

    // Publish to MQTT: the same topics as k528 shop publish, into a broker
    // started here; the poller goes on while the page is hidden.
    void publishesToMqtt() {
        if (!mosquittoInstalled())
            QSKIP("mosquitto is not installed");
        MqttBroker broker;
        QVERIFY(broker.start(freePorts(1).at(0)));
        {
            MainWindow w(loadMachine("training-lathe"));
            w.show();
            QVERIFY(QTest::qWaitForWindowExposed(&w));
            QVERIFY(w.workspaces()->activate("shop"));
            ShopView* shop = w.shopView();
            shop->brokerBox()->setText(broker.url());
            QSignalSpy on(shop, &ShopView::publishingChanged);
            shop->publishBox()->setChecked(true);
            QTRY_VERIFY_WITH_TIMEOUT(shop->publishing(), 10000);
            QVERIFY(shop->publishState().contains("k528-studio-"));
            // Hidden: the poller goes on for the broker.
            QVERIFY(w.workspaces()->activate("operator"));
            QApplication::processEvents();
            QVERIFY(shop->polling());
            QProcess sub;
            broker.subscribe(sub, "k528/+/state", kMachines, 20);
            QVERIFY(sub.waitForStarted());
            QVERIFY(sub.waitForFinished(30000));
            const QString got = QString::fromUtf8(sub.readAllStandardOutput());
            for (int i = 0; i < kMachines; ++i)
                QVERIFY2(got.contains("k528/" + shopMachineName(i) + "/state {"), qPrintable(got));
            QVERIFY2(got.contains("\"mode\":7"), qPrintable(got));
            shop->publishBox()->setChecked(false);
            QVERIFY(!shop->publishing());
            QApplication::processEvents();
            QVERIFY(!shop->polling());
        }
        // The goodbye: the publisher's status retained as offline, "stopped".
        QProcess sub;
        broker.subscribe(sub, "k528/_publisher/#", 1, 10);
        QVERIFY(sub.waitForFinished(15000));
        const QString bye = QString::fromUtf8(sub.readAllStandardOutput());
        QVERIFY2(bye.contains("\"online\":false") && bye.contains("stopped"), qPrintable(bye));
    }
};

QTEST_MAIN(TestShopView)
#include "test_shop_view.moc"
