#include "shop/shop_view.h"

#include "catalog/messages.h"
#include "controller/controller_dock.h"
#include "controller/link_texts.h"
#include "database/database_ui.h"
#include "session/catalog_texts.h"
#include "session/core_texts.h"
#include "main_window.h"
#include "session/shop_database.h"
#include "db/state_times.h"
#include "shop_poll.h"
#ifdef K528_STUDIO_MQTT
#include "shop_publisher.h"
#endif
#include "workspace/elided_label.h"
#include "workspace/flow_layout.h"

#include <QBarCategoryAxis>
#include <QCheckBox>
#include <QCoreApplication>
#include <QLineEdit>
#include <QSettings>
#include <QBarSet>
#include <QChart>
#include <QChartView>
#include <QDate>
#include <QDateTime>
#include <QEvent>
#include <QFontMetrics>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLegend>
#include <QMouseEvent>
#include <QPushButton>
#include <QScrollArea>
#include <QSplitter>
#include <QSysInfo>
#include <QHorizontalStackedBarSeries>
#include <QStatusBar>
#include <QThread>
#include <QTimer>
#include <QTreeWidget>
#include <QValueAxis>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>

namespace k528::studio {

namespace {

// The chart's sets and the tiles' colours, in this order.
constexpr shop::Activity kActivities[4] = {shop::Activity::Run, shop::Activity::Idle, shop::Activity::Alarm,
                                           shop::Activity::Offline};
constexpr const char* kColors[4] = {"#2e9d4a", "#3a76c4", "#c62828", "#80868b"};

int slotOf(shop::Activity a) {
    for (int i = 0; i < 4; ++i)
        if (kActivities[i] == a)
            return i;
    return 3;
}

QString activityText(shop::Activity a) {
    switch (a) {
    case shop::Activity::Run:
        return ShopView::tr("run");
    case shop::Activity::Idle:
        return ShopView::tr("idle");
    case shop::Activity::Alarm:
        return ShopView::tr("alarm");
    case shop::Activity::Offline:
        return ShopView::tr("offline");
    }
    return {};
}

QString durationText(std::int64_t ms) {
    const std::int64_t s = std::max<std::int64_t>(0, ms) / 1000;
    if (s >= 86400)
        return ShopView::tr("%1 d %2:%3").arg(s / 86400).arg(s / 3600 % 24, 2, 10, QChar('0')).arg(s / 60 % 60, 2, 10, QChar('0'));
    return QStringLiteral("%1:%2:%3").arg(s / 3600, 2, 10, QChar('0')).arg(s / 60 % 60, 2, 10, QChar('0')).arg(s % 60, 2, 10, QChar('0'));
}

QString clockText(std::int64_t unixMs) {
    return QDateTime::fromMSecsSinceEpoch(unixMs).toString(QStringLiteral("HH:mm:ss"));
}

QString alarmText(int n) {
    if (positionerMessageText(n).isEmpty())
        return ShopView::tr("alarm %1").arg(n);
    engine::AlarmView a;
    a.number = n;
    return alarmLine(a);
}

QString modeOf(const link::LiveState& l) {
    QString mode = l.mode >= 1 && l.mode <= 7 ? QStringLiteral("F%1").arg(l.mode) : ShopView::tr("power-on");
    if (l.pcReady)
        mode += QStringLiteral(" «РАБОТА С ПЭВМ»");
    return mode;
}

} // namespace

// ---------------------------------------------------------------- ShopTile

ShopTile::ShopTile(const ShopMachine& machine, QWidget* parent) : QFrame(parent), machine_(machine.name) {
    setObjectName("shop.tile." + machine.name);
    setProperty("shopTile", true); // the style's selector (an object name with dots is none)
    setFrameShape(QFrame::StyledPanel);
    setCursor(Qt::PointingHandCursor);
    setFixedWidth(270);
    setSizePolicy(QSizePolicy::Fixed, QSizePolicy::Fixed);
    auto* lay = new QVBoxLayout(this);
    lay->setContentsMargins(8, 6, 8, 6);
    lay->setSpacing(2);
    auto* top = new QHBoxLayout;
    name_ = new QLabel(machine.name, this);
    name_->setObjectName("shop.tile.name");
    QFont f = name_->font();
    f.setBold(true);
    f.setPointSizeF(f.pointSizeF() * 1.15);
    name_->setFont(f);
    state_label_ = new QLabel(this);
    state_label_->setObjectName("shop.tile.state");
    state_label_->setAlignment(Qt::AlignCenter);
    state_label_->setMinimumWidth(70);
    top->addWidget(name_, 1);
    top->addWidget(state_label_);
    lay->addLayout(top);
    line_ = new QLabel(QString::fromStdString(machine.line), this);
    line_->setObjectName("shop.tile.line");
    line_->setStyleSheet(QStringLiteral("color:#6b7075"));
    QFont small = line_->font();
    small.setPointSizeF(small.pointSizeF() * 0.9);
    line_->setFont(small);
    lay->addWidget(line_);
    // The tile's width is fixed (a grid of tiles): a mode with its note
    // («Режим F7 «РАБОТА С ПЭВМ», выполняется») takes a second line.
    mode_ = new QLabel(this);
    mode_->setObjectName("shop.tile.mode");
    mode_->setWordWrap(true);
    program_ = new QLabel(this);
    program_->setObjectName("shop.tile.program");
    program_->setWordWrap(true);
    alarms_ = new QLabel(this);
    alarms_->setObjectName("shop.tile.alarms");
    alarms_->setWordWrap(true);
    alarms_->setStyleSheet(QStringLiteral("color:#b01c1c"));
    since_ = new QLabel(this);
    since_->setObjectName("shop.tile.since");
    since_->setWordWrap(true);
    transferLabel_ = new QLabel(this);
    transferLabel_->setObjectName("shop.tile.transfer");
    transferLabel_->setWordWrap(true);
    transferLabel_->setFont(small);
    for (QLabel* l : {mode_, program_, alarms_, since_, transferLabel_})
        lay->addWidget(l);
    alarms_->hide();
    retranslate();
}

void ShopTile::setIf(QLabel* label, const QString& text) {
    if (label->text() != text)
        label->setText(text);
}

void ShopTile::showState(const shop::MachineState& s, std::int64_t nowMs) {
    state_ = s;
    shown_ = true;
    const int slot = slotOf(s.activity);
    setIf(state_label_, activityText(s.activity));
    const QString style =
        QStringLiteral("[shopTile=\"true\"] { border: %1px solid %2; border-radius: 4px; background: palette(base); }")
            .arg(current_ ? QStringLiteral("3") : QStringLiteral("1"),
                 current_ ? QStringLiteral("#1d4f91") : QString::fromLatin1(kColors[slot]));
    if (style != styleShown_) {
        styleShown_ = style;
        setStyleSheet(style);
    }
    const QString chip = QStringLiteral("background:%1; color:white; border-radius:3px; padding:1px 6px;")
                             .arg(QString::fromLatin1(kColors[slot]));
    if (state_label_->styleSheet() != chip)
        state_label_->setStyleSheet(chip);
    if (s.online) {
        const link::LiveState& l = s.live;
        QString mode = tr("Mode %1").arg(modeOf(l));
        if (l.running)
            mode += tr(", running");
        setIf(mode_, mode);
        mode_->setToolTip(QString());
        setIf(program_, l.program > 0 ? tr("Program L%1, frame N%2").arg(l.program).arg(l.frame) : tr("No program"));
        QStringList a;
        for (int n : l.alarms)
            a << alarmText(n);
        if (a.isEmpty() && l.alarm)
            a << tr("Alarm (no number)");
        setIf(alarms_, a.join(QLatin1Char('\n')));
        alarms_->setVisible(!a.isEmpty());
    } else {
        setIf(mode_, tr("The line does not answer"));
        mode_->setToolTip(why_.empty() ? QString::fromStdString(s.why) : linkText(why_));
        setIf(program_, s.everOnline ? tr("Last answer at %1").arg(clockText(s.lastSeenMs)) : tr("No answer yet"));
        setIf(alarms_, QString());
        alarms_->hide();
    }
    showTime(nowMs);
}

void ShopTile::showTime(std::int64_t nowMs) {
    if (!shown_) {
        setIf(since_, tr("Polling..."));
        return;
    }
    setIf(since_, tr("%1 in this state, since %2").arg(durationText(nowMs - state_.sinceMs), clockText(state_.sinceMs)));
}

void ShopTile::setLastTransfer(const QString& text) {
    transfer_ = text;
    setIf(transferLabel_, text.isEmpty() ? tr("No transfer on record") : tr("Last transfer: %1").arg(text));
}

void ShopTile::setCurrent(bool current) {
    if (current_ == current)
        return;
    current_ = current;
    if (shown_)
        showState(state_, shop::unixMsNow());
    else
        setStyleSheet(current ? QStringLiteral("[shopTile=\"true\"] { border: 3px solid #1d4f91; border-radius: 4px; }")
                              : QString());
}

void ShopTile::retranslate() {
    setToolTip(tr("Click: show this machine's controller on every view of the window"));
    if (shown_)
        showState(state_, shop::unixMsNow());
    else {
        setIf(state_label_, QStringLiteral("…"));
        setIf(mode_, QString());
        setIf(program_, QString());
        showTime(0);
    }
}

QString ShopTile::stateText() const { return state_label_->text(); }
QString ShopTile::offlineReason() const { return mode_->toolTip(); }
QString ShopTile::modeText() const { return mode_->text(); }
QString ShopTile::alarmsText() const { return alarms_->text(); }

void ShopTile::mouseReleaseEvent(QMouseEvent* event) {
    if (event->button() == Qt::LeftButton && rect().contains(event->position().toPoint()))
        emit clicked(machine_);
    QFrame::mouseReleaseEvent(event);
}

// ---------------------------------------------------------------- ShopView

ShopView::ShopView(MainWindow* window) : QWidget(window), window_(window) {
    setObjectName("shopView");
    timesSource_ = "studio@" + QSysInfo::machineHostName().toStdString();
    build();
    clock_ = new QTimer(this);
    clock_->setInterval(1000);
    connect(clock_, &QTimer::timeout, this, &ShopView::tick);
    connect(DatabaseWatch::instance(), &DatabaseWatch::switched, this, [this] { reload(); });
    if (auto* dock = window_->findChild<ControllerDock*>()) {
        connect(dock, &ControllerDock::connectedChanged, this, [this] { markCurrent(); });
        connect(dock, &ControllerDock::transferFinished, this, [this] { readTransfers(); });
    }
    reload();
    // Every way out of the studio (the window closed, --screenshot and
    // --first-frame quitting the event loop, a session's end) says the
    // publisher's goodbye: the window may outlive the loop undestroyed.
    connect(qApp, &QCoreApplication::aboutToQuit, this, &ShopView::goodbye);
    // Publishing is a setting: on again at the next start.
    if (QSettings().value("shop/publish").toBool())
        QTimer::singleShot(0, this, [this] { publish_->setChecked(true); });
}

ShopView::~ShopView() {
    goodbye();
    ++*generation_;
    if (poller_)
        poller_->stop();
    poller_.reset();
    for (QThread* t : retiring_) {
        t->disconnect(this);
        t->wait();
        delete t;
    }
}

void ShopView::goodbye() {
    writeStateTimes(); // the time counted since the last minute
    // A connection being made or a goodbye being said finishes first: a
    // publisher that connected meanwhile says its goodbye below too.
    for (QThread* t : stopping_) {
        t->disconnect(this);
        t->wait();
        delete t;
    }
    stopping_.clear();
#ifdef K528_STUDIO_MQTT
    if (connecting_)
        connecting_->stop(3000); // nothing to say when it never connected
    if (mqtt_)
        mqtt_->stop(3000); // the goodbye, not the will
#endif
    connecting_.reset();
    mqtt_.reset();
}

void ShopView::build() {
    auto* lay = new QVBoxLayout(this);
    lay->setContentsMargins(6, 6, 6, 6);
    auto* head = new QHBoxLayout;
    // Wrapped, whole: a sentence (no machine has a line, the database cannot
    // be read) cut in its middle told nothing; a long database path takes a
    // second line.
    header_ = new QLabel(this);
    header_->setObjectName("shop.header");
    header_->setTextFormat(Qt::PlainText);
    header_->setWordWrap(true);
    header_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    reload_ = new QPushButton(this);
    reload_->setObjectName("shop.reload");
    connect(reload_, &QPushButton::clicked, this, &ShopView::reload);
    head->addWidget(header_, 1);
    head->addWidget(reload_);
    lay->addLayout(head);
    auto* pub = new QHBoxLayout;
    publish_ = new QCheckBox(this);
    publish_->setObjectName("shop.publish");
    brokerCaption_ = new ElidedLabel(this);
    broker_ = new QLineEdit(this);
    broker_->setObjectName("shop.broker");
    broker_->setText(QSettings().value("shop/broker", QStringLiteral("mqtt://localhost:1883")).toString());
    broker_->setMinimumWidth(200);
    broker_->setMaximumWidth(320);
    brokerCaption_->setBuddy(broker_);
    publishState_ = new ElidedLabel(this); // cut rather than widen the window
    publishState_->setObjectName("shop.publishState");
    publishState_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    pub->addWidget(publish_);
    pub->addWidget(brokerCaption_);
    pub->addWidget(broker_);
    pub->addWidget(publishState_, 1);
    lay->addLayout(pub);
    connect(publish_, &QCheckBox::toggled, this, &ShopView::setPublishing);
#ifndef K528_STUDIO_MQTT
    publish_->setEnabled(false); // built without libmosquitto
    broker_->setEnabled(false);
#endif

    auto* split = new QSplitter(Qt::Vertical, this);
    split->setObjectName("shop.split");
    split->setChildrenCollapsible(false);
    auto* scroll = new QScrollArea(split);
    scroll->setObjectName("shop.tiles");
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    tileArea_ = new QWidget(scroll);
    new FlowLayout(tileArea_, 8, 8);
    scroll->setWidget(tileArea_);
    scroll->setMinimumHeight(60);

    auto* bottom = new QSplitter(Qt::Horizontal, split);
    bottom->setChildrenCollapsible(false);
    alarmsBox_ = new QGroupBox(bottom);
    auto* al = new QVBoxLayout(alarmsBox_);
    al->setContentsMargins(4, 4, 4, 4);
    alarms_ = new QTreeWidget(alarmsBox_);
    alarms_->setObjectName("shop.alarms");
    alarms_->setColumnCount(4);
    alarms_->setRootIsDecorated(false);
    alarms_->setUniformRowHeights(true);
    alarms_->header()->setStretchLastSection(true);
    al->addWidget(alarms_);
    chartBox_ = new QGroupBox(bottom);
    auto* cl = new QVBoxLayout(chartBox_);
    cl->setContentsMargins(4, 4, 4, 4);
    chart_ = new QChart;
    chart_->setAnimationOptions(QChart::NoAnimation);
    chart_->legend()->setAlignment(Qt::AlignBottom);
    chart_->setMargins(QMargins(2, 2, 2, 2));
    auto* series = new QHorizontalStackedBarSeries(chart_);
    for (int i = 0; i < 4; ++i) {
        sets_[static_cast<std::size_t>(i)] = new QBarSet(QString(), series);
        sets_[static_cast<std::size_t>(i)]->setColor(QColor(QString::fromLatin1(kColors[i])));
        series->append(sets_[static_cast<std::size_t>(i)]);
    }
    chart_->addSeries(series);
    machinesAxis_ = new QBarCategoryAxis(chart_);
    minutesAxis_ = new QValueAxis(chart_);
    minutesAxis_->setLabelFormat(QStringLiteral("%.0f"));
    chart_->addAxis(machinesAxis_, Qt::AlignLeft);
    chart_->addAxis(minutesAxis_, Qt::AlignBottom);
    series->attachAxis(machinesAxis_);
    series->attachAxis(minutesAxis_);
    // A bar a machine, each tall enough for its name (a shop's sixteen or
    // more scroll rather than shrink to «…»).
    chartScroll_ = new QScrollArea(chartBox_);
    chartScroll_->setObjectName("shop.chartScroll");
    chartScroll_->setWidgetResizable(true);
    chartScroll_->setFrameShape(QFrame::NoFrame);
    chartScroll_->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    chartView_ = new QChartView(chart_, chartScroll_);
    chartView_->setObjectName("shop.chart");
    chartView_->setRenderHint(QPainter::Antialiasing);
    chartView_->setMinimumHeight(90);
    chartView_->setMinimumWidth(160); // not the chart's own hint: the page must fit 1366 px
    chartScroll_->setWidget(chartView_);
    cl->addWidget(chartScroll_);
    bottom->setStretchFactor(0, 1);
    bottom->setStretchFactor(1, 1);
    split_ = split;
    lay->addWidget(split, 1);
    retranslate();
}

void ShopView::retranslate() {
    reload_->setText(tr("Reload"));
    reload_->setToolTip(tr("Read the database's machines and their lines again"));
    alarmsBox_->setTitle(tr("Alarms raised and cleared"));
    chartBox_->setTitle(tr("Today: minutes in each state"));
    alarms_->setHeaderLabels({tr("Time"), tr("Machine"), tr("Event"), tr("Alarm")});
    const QString names[4] = {tr("run"), tr("idle"), tr("alarm"), tr("offline")};
    for (int i = 0; i < 4; ++i)
        sets_[static_cast<std::size_t>(i)]->setLabel(names[i]);
    minutesAxis_->setTitleText(tr("minutes"));
    publish_->setText(tr("Publish to MQTT"));
    publish_->setToolTip(tr("Every machine's state (retained) and each alarm raised or cleared to the MQTT broker, "
                            "in the topics of k528 shop publish (k528/<machine>/state, k528/<machine>/alarms); "
                            "the machines are polled while this is on, whatever page is shown"));
    brokerCaption_->setText(tr("Broker"));
    setPublishState(QString(), publishDetail_);
    if (!dbError_.isEmpty())
        header_->setText(tr("The database cannot be read: %1").arg(dbError_));
    else if (machines_.empty())
        header_->setText(tr("No machine of the database %1 keeps its controller's line: set a machine's line "
                            "(Modbus TCP or serial) in the database to see it here.")
                             .arg(ShopDatabase::currentText()));
    else
        header_->setText(tr("Machines of the database %1 on their lines: %2; each line polled every %3 ms")
                             .arg(ShopDatabase::currentText())
                             .arg(machines_.size())
                             .arg(kIntervalMs));
    for (ShopTile* t : tiles_)
        t->retranslate();
    readTransfers();
}

void ShopView::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QWidget::changeEvent(event);
}

void ShopView::showEvent(QShowEvent* event) {
    QWidget::showEvent(event);
    if (!sized_)
        QTimer::singleShot(0, this, [this] {
            // The tiles first: three fifths of the page, the alarms and the chart below.
            const int h = split_->height();
            if (sized_ || h < 150)
                return;
            sized_ = true;
            split_->setSizes({h * 3 / 5, h - h * 3 / 5});
            if (auto* bottom = qobject_cast<QSplitter*>(split_->widget(1))) {
                const int bw = bottom->width();
                bottom->setSizes({bw * 2 / 5, bw - bw * 2 / 5});
            }
        });
    startPolling();
    clock_->start();
    tick();
}

void ShopView::hideEvent(QHideEvent* event) {
    QWidget::hideEvent(event);
    clock_->stop();
    if (!mqtt_ && !connecting_) // publishing polls whether shown or not
        stopPolling();
}

QString ShopView::publishState() const { return publishState_->text(); }

void ShopView::setPublishState(const QString&, const QString& detail) {
    publishDetail_ = detail;
    QString text;
    switch (publishKind_) {
    case 0:
        text = QString();
        break;
    case 1:
        text = tr("Connecting to the broker...");
        break;
    case 2:
#ifdef K528_STUDIO_MQTT
        text = mqtt_ ? tr("Publishing as %1").arg(QString::fromStdString(mqtt_->clientId())) : QString();
#endif
        break;
    case 3:
        text = tr("Not publishing: the broker cannot be reached (see the tool tip)");
        break;
    }
    publishState_->setText(text);
    publishState_->setToolTip(detail);
}

void ShopView::retirePublisher(std::shared_ptr<shop::MqttPublisher> p) {
    if (!p)
        return;
#ifdef K528_STUDIO_MQTT
    // The goodbye and the wait for the broker's acknowledgements: off the window's thread.
    QThread* t = QThread::create([p] { p->stop(3000); });
    connect(t, &QThread::finished, this, [this, t] {
        stopping_.erase(std::remove(stopping_.begin(), stopping_.end(), t), stopping_.end());
        t->wait();
        delete t;
    });
    stopping_.push_back(t);
    t->start();
#endif
}

void ShopView::setPublishing(bool on) {
#ifndef K528_STUDIO_MQTT
    (void)on;
    publish_->setChecked(false);
#else
    if (publish_->isChecked() != on) {
        publish_->setChecked(on); // toggled() comes back here
        return;
    }
    QSettings().setValue("shop/publish", on);
    if (!on) {
        retirePublisher(std::move(mqtt_));
        mqtt_.reset();
        connecting_.reset(); // its connection, when it comes, is closed at once
        publishKind_ = 0;
        setPublishState(QString());
        broker_->setEnabled(true);
        if (!isVisible())
            stopPolling();
        emit publishingChanged(false);
        return;
    }
    if (mqtt_ || connecting_)
        return;
    const QString url = broker_->text().trimmed();
    QSettings().setValue("shop/broker", url);
    util::Message error;
    if (!mqtt::parseUrl(url.toStdString(), error)) {
        publishKind_ = 3;
        setPublishState(QString(), systemText(error)); // in the window's language
        // Unchecked quietly, as when the broker cannot be reached: toggled()
        // would come back to the switching off above and clear why.
        const QSignalBlocker quiet(publish_);
        publish_->setChecked(false);
        QSettings().setValue("shop/publish", false);
        emit publishingChanged(false);
        return;
    }
    auto p = std::make_shared<shop::MqttPublisher>();
    connecting_ = p;
    broker_->setEnabled(false);
    publishKind_ = 1;
    setPublishState(QString());
    std::vector<std::string> names;
    for (const ShopMachine& m : machines_)
        names.push_back(m.name.toStdString());
    const std::string id = shop::MqttPublisher::defaultClientId("k528-studio");
    auto result = std::make_shared<std::string>();
    auto ok = std::make_shared<bool>(false);
    QThread* t = QThread::create([p, url, id, names, result, ok] {
        *ok = p->start(url.toStdString(), id, kIntervalMs, names, *result);
    });
    connect(t, &QThread::finished, this, [this, t, p, result, ok] {
        stopping_.erase(std::remove(stopping_.begin(), stopping_.end(), t), stopping_.end());
        t->wait();
        delete t;
        if (connecting_ != p) { // switched off meanwhile
            if (*ok)
                retirePublisher(p);
            return;
        }
        connecting_.reset();
        if (!*ok) {
            publishKind_ = 3;
            setPublishState(QString(), QString::fromStdString(*result));
            broker_->setEnabled(true);
            const QSignalBlocker quiet(publish_);
            publish_->setChecked(false);
            QSettings().setValue("shop/publish", false);
            emit publishingChanged(false);
            return;
        }
        mqtt_ = p;
        publishKind_ = 2;
        setPublishState(QString());
        // What is known now, retained at once; the rest as the polls come.
        const std::int64_t now = shop::unixMsNow();
        std::string error;
        for (const shop::Tracker& tk : trackers_)
            if (tk.state().polled)
                mqtt_->publish(tk.state(), true, {}, now, error);
        startPolling();
        emit publishingChanged(true);
    });
    stopping_.push_back(t); // waited for with the goodbyes when the view goes
    t->start();
#endif
}

void ShopView::reload() {
    const bool wasPolling = poller_ != nullptr;
    stopPolling(); // writes what was counted
    dbError_.clear();
    machines_ = shopMachines(&dbError_);
    for (ShopTile* t : tiles_)
        delete t;
    tiles_.clear();
    trackers_.clear();
    today_.assign(machines_.size(), {});
    lastPollMs_.assign(machines_.size(), 0);
    chartShown_.assign(machines_.size(), {-1, -1, -1, -1});
    day_ = QDate::currentDate().toJulianDay();
    QStringList names;
    for (const ShopMachine& m : machines_) {
        trackers_.emplace_back(m.name.toStdString(), m.line);
        auto* t = new ShopTile(m, tileArea_);
        connect(t, &ShopTile::clicked, this, &ShopView::tileClicked);
        tileArea_->layout()->addWidget(t);
        tiles_.push_back(t);
        names << m.name;
    }
    readStateTimes();
    machinesAxis_->clear();
    // A horizontal bar chart lists its first category at the bottom: the
    // names go in reversed, so the chart reads top-down as the tiles do.
    QStringList bottomUp(names.crbegin(), names.crend());
    machinesAxis_->append(bottomUp);
    for (QBarSet* s : sets_) {
        s->remove(0, s->count());
        for (qsizetype i = 0; i < names.size(); ++i)
            s->append(0.0);
    }
    minutesAxis_->setRange(0, 10);
    minutesAxis_->setTickCount(6);
    // The axes, the legend and the margins take about 110 px; a bar is as
    // tall as its machine's name with room around it.
    const int bar = QFontMetrics(machinesAxis_->labelsFont()).height() * 2;
    chartView_->setMinimumHeight(std::max(90, bar * static_cast<int>(names.size()) + 110));
    retranslate();
    markCurrent();
    updateChart(true);
    if (wasPolling || isVisible())
        startPolling();
}

void ShopView::readStateTimes() {
    if (machines_.empty())
        return;
    const std::string day = shop::localDay(shop::unixMsNow());
    try {
        const std::vector<db::StateTime> rows = ShopDatabase::at(ShopDatabase::current())->use(
            [&](db::Database& d) { return db::stateTimes(d, day, timesSource_); });
        for (const db::StateTime& r : rows)
            for (std::size_t i = 0; i < machines_.size(); ++i)
                if (machines_[i].name.toStdString() == r.machine)
                    for (int k = 0; k < 4; ++k)
                        if (r.state == shop::activityName(kActivities[k]))
                            today_[i][static_cast<std::size_t>(k)] = r.ms;
    } catch (const std::exception&) {
        // an older or unreadable database: today's times start from nothing
    }
}

void ShopView::writeStateTimes() {
    const std::int64_t now = shop::unixMsNow();
    tally_.due(now); // starts the minute at the first call
    if (tally_.empty())
        return;
    const std::vector<shop::StateTally::Row> rows = tally_.take(now);
    std::vector<db::StateTime> out;
    for (const shop::StateTally::Row& r : rows)
        out.push_back({r.machine, r.day, timesSource_, r.state, r.ms, {}});
    try {
        ShopDatabase::at(ShopDatabase::current())->use([&](db::Database& d) { db::addStateTimes(d, out); });
    } catch (const std::exception& e) {
        // Kept for the next minute (a busy or unreachable database); a
        // database that cannot take them (read-only, an older schema, a
        // viewer's role) keeps them for the session's chart only.
        const auto* error = dynamic_cast<const db::Error*>(&e);
        if (error && (error->kind() == db::ErrorKind::Busy || error->kind() == db::ErrorKind::Io))
            tally_.putBack(rows);
    }
}

void ShopView::readTransfers() {
    if (tiles_.empty())
        return;
    try {
        ShopDatabase::at(ShopDatabase::current())->use([&](db::Database& d) {
            for (std::size_t i = 0; i < machines_.size(); ++i) {
                db::TransferFilter f;
                f.machine = machines_[i].name.toStdString();
                f.limit = 1;
                const std::vector<db::TransferEntry> last = d.transfers(f);
                if (last.empty()) {
                    tiles_[i]->setLastTransfer(QString());
                    continue;
                }
                const db::TransferEntry& e = last.back();
                const QString dir = e.direction == "push" ? tr("push") : tr("pull");
                const QString result = e.result == "ok" ? tr("ok") : e.result == "partial" ? tr("partial") : tr("failed");
                QDateTime at = QDateTime::fromString(QString::fromStdString(e.at), Qt::ISODateWithMs);
                const QString when = at.isValid() ? at.toLocalTime().toString(QStringLiteral("yyyy-MM-dd HH:mm"))
                                                  : QString::fromStdString(e.at);
                tiles_[i]->setLastTransfer(tr("%1 %2, %3").arg(dir, result, when));
            }
        });
    } catch (const std::exception&) {
        // the header says when the database cannot be read
    }
}

void ShopView::startPolling() {
    if (poller_ || machines_.empty())
        return;
    std::vector<shop::LineRef> lines;
    for (const ShopMachine& m : machines_)
        lines.push_back({m.name.toStdString(), m.address});
    QString error;
    auto p = std::make_unique<shop::Poller>(std::move(lines), kTimeoutMs, error);
    if (!p->ok()) {
        header_->setText(tr("The machines cannot be polled: %1").arg(error));
        return;
    }
    poller_ = std::move(p);
    std::fill(lastPollMs_.begin(), lastPollMs_.end(), 0); // the time unpolled counts for no state
    const int gen = ++*generation_;
    const std::shared_ptr<std::atomic<int>> g = generation_;
    poller_->start(kIntervalMs, [this, g, gen](const shop::PollResult& r) {
        if (g->load() != gen)
            return;
        QMetaObject::invokeMethod(
            this, [this, g, gen, r] {
                if (g->load() == gen)
                    apply(r);
            },
            Qt::QueuedConnection);
    });
}

void ShopView::stopPolling() {
    if (!poller_)
        return;
    ++*generation_;
    writeStateTimes();
    // Stopped off the window's thread: a worker waits for its line's answer.
    shop::Poller* p = poller_.release();
    QThread* t = QThread::create([p] { delete p; });
    connect(t, &QThread::finished, this, [this, t] {
        retiring_.erase(std::remove(retiring_.begin(), retiring_.end(), t), retiring_.end());
        t->wait();
        delete t;
    });
    retiring_.push_back(t);
    t->start();
}

void ShopView::apply(const shop::PollResult& r) {
    if (r.index >= trackers_.size())
        return;
    const qint64 day = QDate::currentDate().toJulianDay();
    if (day != day_) { // a new day: today's times begin again
        day_ = day;
        for (auto& d : today_)
            d = {};
    }
    const std::size_t i = r.index;
    shop::Tracker& tk = trackers_[i];
    const shop::Activity before = tk.state().activity;
    if (tk.state().polled && lastPollMs_[i] > 0) {
        const std::int64_t ms = std::max<std::int64_t>(0, r.atMs - lastPollMs_[i]);
        today_[i][static_cast<std::size_t>(slotOf(before))] += ms;
        tally_.add(tk.state().machine, shop::localDay(r.atMs), before, ms);
    }
    lastPollMs_[i] = r.atMs;
    std::vector<shop::AlarmEvent> events;
    const bool changed = tk.update(r.online ? &r.live : nullptr, r.why, r.atMs, events);
    tiles_[i]->setOfflineReason(r.online ? link::Said() : r.said);
    if (changed)
        tiles_[i]->showState(tk.state(), r.atMs);
    for (const shop::AlarmEvent& e : events) {
        auto* item = new QTreeWidgetItem(QStringList{clockText(e.atMs), machines_[i].name,
                                          e.raised ? ShopView::tr("raised") : ShopView::tr("cleared"),
                                          alarmText(e.number)});
        if (e.raised)
            item->setForeground(3, QColor(0xb0, 0x1c, 0x1c));
        alarms_->insertTopLevelItem(0, item);
        while (alarms_->topLevelItemCount() > 500)
            delete alarms_->takeTopLevelItem(alarms_->topLevelItemCount() - 1);
    }
#ifdef K528_STUDIO_MQTT
    if (mqtt_) {
        std::string error;
        mqtt_->publish(tk.state(), changed, events, r.atMs, error);
    }
#endif
    if (tk.state().activity != before) {
        tally_.changed(); // the time up to the change goes to the database now
        writeStateTimes();
        updateChart();
    }
    if (changed)
        emit machineChanged(machines_[i].name);
    emit polled();
}

void ShopView::tick() {
    const std::int64_t now = shop::unixMsNow();
    if (tally_.due(now)) // once a minute
        writeStateTimes();
    for (ShopTile* t : tiles_)
        t->showTime(now);
    updateChart();
}

void ShopView::updateChart(bool force) {
    // Tenths of a minute: the chart redraws at most every six seconds.
    bool changed = force;
    double most = 0;
    for (std::size_t i = 0; i < today_.size(); ++i) {
        double total = 0;
        for (std::size_t k = 0; k < 4; ++k) {
            const int tenths = static_cast<int>(today_[i][k] / 6000);
            total += tenths / 10.0;
            if (tenths != chartShown_[i][k]) {
                chartShown_[i][k] = tenths;
                sets_[k]->replace(static_cast<qsizetype>(today_.size() - 1 - i), tenths / 10.0);
                changed = true;
            }
        }
        most = std::max(most, total);
    }
    if (changed) {
        const double top = most <= 10 ? 10 : most <= 60 ? 60 : std::ceil(most / 60.0) * 60.0;
        if (minutesAxis_->max() != top) {
            minutesAxis_->setRange(0, top);
            minutesAxis_->setTickCount(top <= 10 ? 6 : top <= 60 ? 7 : 5);
        }
    }
}

std::array<std::int64_t, 4> ShopView::today(const QString& machine) const {
    for (std::size_t i = 0; i < machines_.size(); ++i)
        if (machines_[i].name == machine)
            return today_[i];
    return {};
}

ShopTile* ShopView::tile(const QString& machine) const {
    for (ShopTile* t : tiles_)
        if (t->machine() == machine)
            return t;
    return nullptr;
}

const shop::MachineState* ShopView::state(const QString& machine) const {
    for (std::size_t i = 0; i < machines_.size(); ++i)
        if (machines_[i].name == machine)
            return &trackers_[i].state();
    return nullptr;
}

void ShopView::tileClicked(const QString& machine) {
    auto* dock = window_->findChild<ControllerDock*>();
    if (!dock)
        return;
    if (!dock->connectMachine(machine))
        window_->statusBar()->showMessage(
            tr("The controller of %1 cannot be shown now: the Controller dock's line is busy").arg(machine), 10000);
    else
        window_->statusBar()->showMessage(tr("Connecting to the controller of %1...").arg(machine), 10000);
    markCurrent();
}

void ShopView::markCurrent() {
    auto* dock = window_->findChild<ControllerDock*>();
    const QString current = dock && dock->link() ? dock->connectedMachine() : QString();
    for (ShopTile* t : tiles_)
        t->setCurrent(t->machine() == current);
}

} // namespace k528::studio
