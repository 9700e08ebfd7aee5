#include "machine/machine_panel.h"

#include "machine/pendant_controls.h"
#include "session/simulation_session.h"
#include "window_language.h"

#include "profile/english.h"

#include <QEvent>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLinearGradient>
#include <QPainter>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>

namespace k528::studio {

namespace {

constexpr int kOverrideSteps[] = {0, 1, 2, 5, 10, 20, 35, 50, 75, 90, 100};

// Lamps shown in the strip (the start, stop and drives lamps are in their buttons).
bool inStrip(const std::string& id) {
    return id != "cycle_start" && id != "cycle_stop" && id != "drives" && id != "reset";
}

PilotLamp::Color lampColorOf(const std::string& id) {
    if (id == "alarm" || id == "limit")
        return PilotLamp::Color::Red;
    if (id == "door")
        return PilotLamp::Color::Amber;
    if (id == "reference" || id == "gauge")
        return PilotLamp::Color::Blue;
    if (id == "lube" || id == "hydraulics" || id == "turret")
        return PilotLamp::Color::White;
    return PilotLamp::Color::Green;
}

int px(double v, double scale) { return static_cast<int>(std::lround(v * scale)); }

QString readoutStyle(double s) {
    return QStringLiteral("QLabel { background: #0d1410; color: #7cf08e; border: 2px solid #55595e;"
                          " border-radius: %1px; padding: %2px %3px;"
                          " font-family: 'DejaVu Sans Mono', 'Liberation Mono', monospace; font-size: %4px; }")
        .arg(px(4, s))
        .arg(px(4, s))
        .arg(px(8, s))
        .arg(std::max(7, px(12, s)));
}

QString captionStyle(double s) {
    return QStringLiteral("QLabel { color: #e8e6dc; font-weight: bold; font-size: %1px; letter-spacing: 1px; }")
        .arg(std::max(7, px(11, s)));
}

QLabel* readoutLabel(QWidget* parent, const char* name) {
    auto* l = new QLabel(parent);
    l->setObjectName(name);
    l->setTextFormat(Qt::RichText);
    l->setProperty("k528.style", "readout");
    l->setStyleSheet(readoutStyle(1));
    l->setMinimumHeight(26);
    return l;
}

QLabel* caption(QWidget* parent) {
    auto* l = new QLabel(parent);
    l->setAlignment(Qt::AlignCenter);
    l->setProperty("k528.style", "caption");
    l->setStyleSheet(captionStyle(1));
    return l;
}

// The sizes set at scale 1, kept on the widget for setScale.
void fixedSize(QWidget* w, int width, int height) {
    w->setProperty("k528.fixedSize", QSize(width, height));
    w->setFixedSize(width, height);
}

QString led(bool on, const QString& color) {
    return QStringLiteral("<span style='color:%1'>%2</span>")
        .arg(on ? color : QStringLiteral("#2c3a30"), QStringLiteral("●"));
}

} // namespace

MachinePanelWidget::MachinePanelWidget(SimulationSession& session, QWidget* parent)
    : QWidget(parent), session_(session) {
    setObjectName("machinePanel");
    setAttribute(Qt::WA_OpaquePaintEvent);
    build();
    retranslate();
    connect(&session_, &SimulationSession::advanced, this, &MachinePanelWidget::refresh);
    refresh();
}

PilotLamp* MachinePanelWidget::lamp(const QString& id) const {
    const auto it = lamps_.find(id.toStdString());
    return it == lamps_.end() ? nullptr : it->second;
}

void MachinePanelWidget::build() {
    const machine::MachineView v = session_.simulation().view();
    auto* outer = outer_ = new QVBoxLayout(this);
    outer->setContentsMargins(14, 10, 14, 10);
    outer->setSpacing(4);
    title_ = caption(this);
    title_->setObjectName("machine.title");
    title_->setWordWrap(true);
    outer->addWidget(title_);
    auto* columns = columns_ = new QHBoxLayout;
    columns->setSpacing(14);
    outer->addLayout(columns, 1);
    // Left: E-stop, cycle, jog, lamps. Right: handwheel, override, door,
    // chuck, read-outs.
    left_ = new QVBoxLayout;
    left_->setSpacing(4);
    right_ = new QVBoxLayout;
    right_->setSpacing(4);
    columns->addLayout(left_, 1);
    columns->addLayout(right_, 1);

    buildCycleControls();
    buildJog();
    if (v.hasHandwheel)
        buildHandwheel();
    buildOverrideDoorChuck(v);
    buildLamps(v);
    left_->addStretch();
    buildReadouts(v);
    right_->addStretch();
}

PendantButton* MachinePanelWidget::makeButton(machine::Button b, PendantButton::Cap cap, const char* name,
                                              bool illuminated) {
    auto* btn = new PendantButton(cap, this);
    btn->setObjectName(name);
    btn->setIlluminated(illuminated);
    buttons_[b] = btn;
    connect(btn, &QAbstractButton::pressed, this, [this, b] {
        session_.simulation().press(b);
        pressedAtMs_[b] = session_.simulation().timeMs();
    });
    connect(btn, &QAbstractButton::released, this, [this, b] {
        // A click shorter than a push stays down until it was one.
        machine::Simulation& sim = session_.simulation();
        const auto at = pressedAtMs_.find(b);
        const std::int64_t held = at == pressedAtMs_.end() ? kShortestPushMs : sim.timeMs() - at->second;
        if (held >= kShortestPushMs)
            sim.release(b);
        else
            sim.pressFor(b, kShortestPushMs - held);
    });
    return btn;
}

// E-stop, drives, cycle.
void MachinePanelWidget::buildCycleControls() {
    auto* top = new QHBoxLayout;
    top->setSpacing(8);
    estop_ = new MushroomButton(this);
    estop_->setObjectName("machine.estop");
    connect(estop_, &QAbstractButton::toggled, this, [this](bool pressed) {
        if (pressed)
            session_.simulation().pressEmergencyStop();
        else
            session_.simulation().releaseEmergencyStop();
    });
    top->addWidget(estop_, 0, Qt::AlignVCenter);
    auto* cycle = new QGridLayout;
    cycle->setHorizontalSpacing(6);
    cycle->setVerticalSpacing(4);
    using Cap = PendantButton::Cap;
    cycle->addWidget(makeButton(machine::Button::DrivesOn, Cap::White, "machine.drivesOn", true), 0, 0);
    cycle->addWidget(makeButton(machine::Button::Reset, Cap::Blue, "machine.reset", false), 0, 1);
    cycle->addWidget(makeButton(machine::Button::CycleStart, Cap::Green, "machine.cycleStart", true), 1, 0);
    cycle->addWidget(makeButton(machine::Button::CycleStop, Cap::Red, "machine.cycleStop", true), 1, 1);
    top->addLayout(cycle, 1);
    left_->addLayout(top);
}

// Jog ±X ±Z around rapid.
void MachinePanelWidget::buildJog() {
    jogLabel_ = caption(this);
    left_->addWidget(jogLabel_);
    auto* jog = new QGridLayout;
    jog->setSpacing(2);
    const auto jogButton = [&](machine::Button b, const char* name, const char* symbol) {
        PendantButton* btn = makeButton(b, PendantButton::Cap::Black, name, false);
        btn->setSymbol(QString::fromUtf8(symbol));
        fixedSize(btn, 54, 50);
        return btn;
    };
    // A lathe's view: X across (up = +X, away from the spindle axis), Z along.
    jog->addWidget(jogButton(machine::Button::JogXPlus, "machine.jog.x+", "+X"), 0, 1, Qt::AlignCenter);
    jog->addWidget(jogButton(machine::Button::JogZMinus, "machine.jog.z-", "−Z"), 1, 0, Qt::AlignCenter);
    PendantButton* rapid = makeButton(machine::Button::Rapid, PendantButton::Cap::Yellow, "machine.rapid", false);
    rapid->setSymbol(QString::fromUtf8("⇶"));
    fixedSize(rapid, 54, 50);
    jog->addWidget(rapid, 1, 1, Qt::AlignCenter);
    jog->addWidget(jogButton(machine::Button::JogZPlus, "machine.jog.z+", "+Z"), 1, 2, Qt::AlignCenter);
    jog->addWidget(jogButton(machine::Button::JogXMinus, "machine.jog.x-", "−X"), 2, 1, Qt::AlignCenter);
    auto* jogRow = new QHBoxLayout;
    jogRow->addStretch();
    jogRow->addLayout(jog);
    jogRow->addStretch();
    left_->addLayout(jogRow);
}

// The pilot lamps of the strip; the illuminated buttons' lamps are reachable by id too.
void MachinePanelWidget::buildLamps(const machine::MachineView& v) {
    auto* lampGrid = new QGridLayout;
    lampGrid->setSpacing(4);
    int n = 0;
    for (const auto& [id, on] : v.lamps) {
        if (!inStrip(id))
            continue;
        auto* l = new PilotLamp(lampColorOf(id), this);
        l->setObjectName(QString::fromStdString("machine.lamp." + id));
        lamps_[id] = l;
        lampGrid->addWidget(l, n / 4, n % 4);
        ++n;
    }
    left_->addLayout(lampGrid);
}

// The handwheel with its axis selector and multiplier.
void MachinePanelWidget::buildHandwheel() {
    handwheelLabel_ = caption(this);
    right_->addWidget(handwheelLabel_);
    dial_ = new HandwheelDial(this);
    dial_->setObjectName("machine.handwheel");
    dial_->setDetentsPerTurn(
        static_cast<int>(session_.simulation().profile().simulation.getInt("handwheel1.lines", 100)));
    fixedSize(dial_, 150, 150);
    connect(dial_, &HandwheelDial::turned, this,
            [this](int detents) { session_.simulation().turnHandwheel(detents); });
    right_->addWidget(dial_, 0, Qt::AlignHCenter);
    auto* sel = new QHBoxLayout;
    wheelAxis_ = new SelectorSwitch(this);
    wheelAxis_->setObjectName("machine.handwheelAxis");
    wheelAxis_->setPositions({"0", "X", "Z"}, 90);
    connect(wheelAxis_, &SelectorSwitch::positionChanged, this, [this](int i) {
        session_.simulation().selectHandwheel(static_cast<machine::HandwheelAxis>(i));
        updateMultiplierLegends();
    });
    wheelMult_ = new SelectorSwitch(this);
    wheelMult_->setObjectName("machine.handwheelMultiplier");
    wheelMult_->setPositions({"×1", "×10", "×100"}, 90);
    connect(wheelMult_, &SelectorSwitch::positionChanged, this,
            [this](int i) { session_.simulation().selectHandwheelMultiplier(i); });
    sel->addWidget(wheelAxis_);
    sel->addWidget(wheelMult_);
    right_->addLayout(sel);
}

// The feed override selector (when the machine has one) beside the door, the
// chuck's foot switch and the grinder's wheel change, those it has.
void MachinePanelWidget::buildOverrideDoorChuck(const machine::MachineView& v) {
    auto* misc = new QHBoxLayout;
    misc->setSpacing(8);
    if (v.hasOverrideSwitch) {
        override_ = new SelectorSwitch(this);
        override_->setObjectName("machine.override");
        QStringList legends{"K923"};
        for (int pct : kOverrideSteps)
            legends << QString::number(pct);
        override_->setPositions(legends, 270);
        override_->setProperty("k528.minimumSize", QSize(150, 128));
        override_->setMinimumSize(150, 128);
        override_->setPosition(session_.simulation().overrideSwitch() + 1);
        connect(override_, &SelectorSwitch::positionChanged, this, [this](int i) {
            session_.simulation().setOverrideSwitch(overrideCodeOfPosition(i));
        });
        misc->addWidget(override_, 3);
    }
    auto* side = new QGridLayout;
    side->setSpacing(6);
    int slot = 0;
    const auto place = [&](QWidget* w) {
        side->addWidget(w, slot / 2, slot % 2);
        ++slot;
    };
    if (v.hasDoor) {
        door_ = new PendantButton(PendantButton::Cap::White, this);
        door_->setObjectName("machine.door");
        door_->setSymbol(QString::fromUtf8("⇆"));
        connect(door_, &QAbstractButton::clicked, this, [this] {
            machine::Simulation& s = session_.simulation();
            if (s.view().doorClosed)
                s.openDoor(); // refused while the lock holds it
            else
                s.closeDoor();
            refresh();
        });
        place(door_);
    }
    if (v.hasChuck) {
        PendantButton* pedal =
            makeButton(machine::Button::ChuckPedal, PendantButton::Cap::Black, "machine.chuck", false);
        pedal->setSymbol(QString::fromUtf8("⊙"));
        place(pedal);
    }
    if (v.hasGrinding) {
        changeWheel_ = new PendantButton(PendantButton::Cap::Yellow, this);
        changeWheel_->setObjectName("machine.changeWheel");
        changeWheel_->setSymbol(QString::fromUtf8("◎"));
        connect(changeWheel_, &QAbstractButton::clicked, this, [this] {
            session_.simulation().changeWheel();
            refresh();
        });
        place(changeWheel_);
    }
    misc->addLayout(side, 2);
    if (override_ || slot > 0)
        right_->addLayout(misc);
    if (override_) {
        overrideLabel_ = new QLabel(this); // accessible caption only
        overrideLabel_->hide();
    }
}

// The spindles, the turret and (grinder) the in-process gauge.
void MachinePanelWidget::buildReadouts(const machine::MachineView& v) {
    readout_ = readoutLabel(this, "machine.readout");
    readout_->setWordWrap(true);
    right_->addWidget(readout_);
    if (v.hasGrinding) {
        gauge_ = readoutLabel(this, "machine.gauge");
        gauge_->setWordWrap(true);
        right_->addWidget(gauge_);
    }
}

QString MachinePanelWidget::lampLegend(const std::string& id) const {
    if (id == "spindle")
        return tr("SPINDLE");
    if (id == "coolant")
        return tr("COOLANT");
    if (id == "limit")
        return tr("LIMIT");
    if (id == "reference")
        return tr("HOMED");
    if (id == "door")
        return tr("DOOR");
    if (id == "chuck")
        return tr("CLAMPED");
    if (id == "alarm")
        return tr("ALARM");
    if (id == "lube")
        return tr("LUBE");
    if (id == "wheel")
        return tr("WHEEL");
    if (id == "gauge")
        return tr("GAUGE");
    if (id == "turret")
        return tr("TURRET");
    if (id == "hydraulics")
        return tr("HYDRAUL.");
    return QString::fromStdString(id);
}

void MachinePanelWidget::retranslate() {
    const machine::Simulation& sim = session_.simulation();
    title_->setText(tr("MACHINE CONTROL PANEL") + "\n" +
                    coreText(profile::titleText(sim.profile(), false), profile::titleText(sim.profile(), true)));
    estop_->setLegend(tr("EMERGENCY STOP"));
    buttons_.at(machine::Button::DrivesOn)->setLegend(tr("DRIVES ON"));
    buttons_.at(machine::Button::Reset)->setLegend(tr("RESET"));
    buttons_.at(machine::Button::CycleStart)->setLegend(tr("CYCLE START"));
    buttons_.at(machine::Button::CycleStop)->setLegend(tr("STOP"));
    buttons_.at(machine::Button::Rapid)->setToolTip(tr("Rapid traverse: hold with a jog button"));
    buttons_.at(machine::Button::JogXPlus)->setToolTip(tr("Jog X+ (hold)"));
    buttons_.at(machine::Button::JogXMinus)->setToolTip(tr("Jog X- (hold)"));
    buttons_.at(machine::Button::JogZPlus)->setToolTip(tr("Jog Z+ (hold)"));
    buttons_.at(machine::Button::JogZMinus)->setToolTip(tr("Jog Z- (hold)"));
    jogLabel_->setText(tr("JOG"));
    if (handwheelLabel_) {
        handwheelLabel_->setText(tr("HANDWHEEL"));
        wheelAxis_->setCaption(tr("AXIS"));
        wheelMult_->setCaption(tr("STEP"));
        dial_->setToolTip(tr("Drag round or turn the mouse wheel: one detent is one step"));
    }
    if (override_) {
        override_->setCaption(tr("FEED OVERRIDE %"));
        override_->setToolTip(tr("K923: the panel's L1..L4 keys set the override"));
    }
    if (door_)
        door_->setLegend(tr("DOOR"));
    if (auto it = buttons_.find(machine::Button::ChuckPedal); it != buttons_.end())
        it->second->setLegend(tr("CHUCK"));
    if (changeWheel_)
        changeWheel_->setLegend(tr("NEW WHEEL"));
    for (auto& [id, l] : lamps_)
        l->setLegend(lampLegend(id));
    updateMultiplierLegends();
    lastReadout_.clear();
    lastGauge_.clear();
}

void MachinePanelWidget::updateMultiplierLegends() {
    if (!wheelMult_)
        return;
    const machine::Simulation& sim = session_.simulation();
    // The positions give what the machine really moves per detent.
    QStringList tips;
    const engine::AxisView ax = sim.controller().axisView(
        sim.view().wheelAxis == machine::HandwheelAxis::Z ? engine::AxisId::Z : engine::AxisId::X);
    for (int step = 0; step < 3; ++step)
        tips << units::formatDisc(sim.handwheelDiscretesPerDetent(step), ax.scale).c_str();
    wheelMult_->setToolTip(tr("Per detent: %1 / %2 / %3 mm").arg(tips[0], tips[1], tips[2]));
}

void MachinePanelWidget::refresh() {
    machine::Simulation& sim = session_.simulation();
    const machine::MachineView v = sim.view();
    const auto lampOn = [&](const char* id) {
        for (const auto& [name, on] : v.lamps)
            if (name == id)
                return on;
        return false;
    };
    buttons_.at(machine::Button::DrivesOn)->setLit(lampOn("drives"));
    buttons_.at(machine::Button::CycleStart)->setLit(lampOn("cycle_start"));
    buttons_.at(machine::Button::CycleStop)->setLit(lampOn("cycle_stop"));
    for (const auto& [id, on] : v.lamps)
        if (auto it = lamps_.find(id); it != lamps_.end())
            it->second->setOn(on);
    if (estop_->isChecked() != v.estopPressed) {
        const QSignalBlocker block(estop_);
        estop_->setChecked(v.estopPressed);
    }
    if (door_)
        door_->setSymbol(v.doorClosed ? QString::fromUtf8("⇆") : QString::fromUtf8("▯"));
    if (dial_)
        dial_->setEnabledLook(v.wheelAxis != machine::HandwheelAxis::Off);
    // The selectors show where the machine's switches stand (a test or a
    // script may have turned them).
    const auto sync = [](SelectorSwitch* s, int position) {
        if (s && s->position() != position) {
            const QSignalBlocker block(s);
            s->setPosition(position);
        }
    };
    sync(wheelAxis_, static_cast<int>(v.wheelAxis));
    sync(wheelMult_, v.wheelStep);
    sync(override_, v.overrideCode + 1);

    // Read-outs: spindles, turret.
    QString text;
    for (const machine::SpindleView& s : v.spindles) {
        QString name = s.name == "spindle" ? tr("Spindle")
                       : s.name == "wheel" ? tr("Wheel")
                                           : tr("Work");
        text +=
            QStringLiteral("%1 %2 %3&nbsp;&nbsp;")
                .arg(name.toHtmlEscaped(),
                     QString::number(std::lround(std::fabs(s.rpm))).rightJustified(5, QChar(0xA0)),
                     tr("rpm"));
        text += led(s.atSpeed, "#7cf08e") + QStringLiteral("&nbsp;&nbsp; ");
    }
    if (v.hasTurret)
        text += tr("Tool %1").arg(v.turretStation == 0 ? QStringLiteral("-")
                                                       : QString::number(v.turretStation)) +
                QStringLiteral(" ") + led(v.turretLocked, "#7cf08e");
    if (text != lastReadout_) {
        readout_->setText(text);
        lastReadout_ = text;
    }
    if (gauge_) {
        const QString g =
            tr("Gauge: bore %1 / %2 mm, wheel %3 mm")
                .arg(v.ringPresent ? QString::number(v.boreMm, 'f', 4) : QStringLiteral("--"))
                .arg(QString::number(v.sizeMm, 'f', 3), QString::number(v.wheelMm, 'f', 3)) +
            QStringLiteral("<br>") + led(v.gaugeIn, "#6cb8ff") + tr(" in ") +
            led(v.touch, "#ffd23c") + tr(" touch ") + led(v.rough, "#7cf08e") + tr(" rough ") +
            led(v.finish, "#7cf08e") + tr(" finish ") + led(v.size, "#ff6a5a") + tr(" size");
        if (g != lastGauge_) {
            gauge_->setText(g);
            lastGauge_ = g;
        }
    }
}

void MachinePanelWidget::setScale(double scale) {
    scale = std::clamp(scale, 0.5, 3.0);
    if (std::abs(scale - scale_) < 0.005)
        return;
    scale_ = scale;
    applyScale();
}

void MachinePanelWidget::setStacked(bool stacked) {
    if (stacked != this->stacked())
        columns_->setDirection(stacked ? QBoxLayout::TopToBottom : QBoxLayout::LeftToRight);
}

bool MachinePanelWidget::stacked() const { return columns_->direction() == QBoxLayout::TopToBottom; }

void MachinePanelWidget::fitTo(QSize room) {
    if (room.isEmpty())
        return;
    // The natural sizes (scale 1) of both arrangements, from the columns'
    // hints at the scale now (they scale linearly).
    const double s = scale_;
    const QMargins m = outer_->contentsMargins();
    const QSize a = left_->sizeHint(), b = right_->sizeHint();
    const double title = title_->sizeHint().height() + outer_->spacing();
    const double gap = columns_->spacing();
    const double mw = m.left() + m.right(), mh = m.top() + m.bottom();
    const double sideW = (a.width() + gap + b.width() + mw) / s, sideH = (std::max(a.height(), b.height()) + title + mh) / s;
    const double stackW = (std::max(a.width(), b.width()) + mw) / s, stackH = (a.height() + gap + b.height() + title + mh) / s;
    const double side = std::min(room.width() / sideW, room.height() / sideH);
    const double stack = std::min(room.width() / stackW, room.height() / stackH);
    // Stacked only when it is clearly larger (no flapping at the edge).
    const bool stacked = stack > side * 1.15;
    setStacked(stacked);
    setScale(std::clamp(std::floor((stacked ? stack : side) * 20) / 20, 0.6, 2.5));
}

void MachinePanelWidget::applyScale() {
    const double s = scale_;
    for (auto* c : findChildren<PendantButton*>())
        c->setScale(s);
    for (auto* c : findChildren<MushroomButton*>())
        c->setScale(s);
    for (auto* c : findChildren<PilotLamp*>())
        c->setScale(s);
    for (auto* c : findChildren<HandwheelDial*>())
        c->setScale(s);
    for (auto* c : findChildren<SelectorSwitch*>())
        c->setScale(s);
    for (auto* w : findChildren<QWidget*>()) {
        if (const QVariant f = w->property("k528.fixedSize"); f.isValid())
            w->setFixedSize(px(f.toSize().width(), s), px(f.toSize().height(), s));
        if (const QVariant m = w->property("k528.minimumSize"); m.isValid())
            w->setMinimumSize(px(m.toSize().width(), s), px(m.toSize().height(), s));
    }
    for (auto* l : findChildren<QLabel*>()) {
        const QString style = l->property("k528.style").toString();
        if (style == QLatin1String("caption"))
            l->setStyleSheet(captionStyle(s));
        else if (style == QLatin1String("readout")) {
            l->setStyleSheet(readoutStyle(s));
            l->setMinimumHeight(px(26, s));
        }
    }
    // Margins and gaps: the values of scale 1 are kept on each layout.
    for (auto* l : findChildren<QLayout*>()) {
        if (!l->property("k528.spacing").isValid()) {
            l->setProperty("k528.spacing", l->spacing());
            const QMargins m = l->contentsMargins();
            l->setProperty("k528.margins", QRect(m.left(), m.top(), m.right(), m.bottom()));
            if (auto* g = qobject_cast<QGridLayout*>(l)) {
                l->setProperty("k528.hspacing", g->horizontalSpacing());
                l->setProperty("k528.vspacing", g->verticalSpacing());
            }
        }
        if (auto* g = qobject_cast<QGridLayout*>(l)) {
            g->setHorizontalSpacing(px(l->property("k528.hspacing").toInt(), s));
            g->setVerticalSpacing(px(l->property("k528.vspacing").toInt(), s));
        } else if (l->property("k528.spacing").toInt() >= 0) {
            l->setSpacing(px(l->property("k528.spacing").toInt(), s));
        }
        const QRect m = l->property("k528.margins").toRect();
        l->setContentsMargins(px(m.x(), s), px(m.y(), s), px(m.width(), s), px(m.height(), s));
    }
    updateGeometry();
}

void MachinePanelWidget::changeEvent(QEvent* e) {
    if (e->type() == QEvent::LanguageChange)
        retranslate();
    QWidget::changeEvent(e);
}

void MachinePanelWidget::paintEvent(QPaintEvent*) {
    // The pendant's housing: powder-coated dark grey with a lighter rim and
    // four screws.
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing);
    QLinearGradient g(0, 0, 0, height());
    g.setColorAt(0, QColor(0x4a, 0x4f, 0x55));
    g.setColorAt(1, QColor(0x33, 0x37, 0x3b));
    p.fillRect(rect(), g);
    p.setPen(QPen(QColor(0x6c, 0x72, 0x78), 2));
    p.setBrush(Qt::NoBrush);
    p.drawRoundedRect(QRectF(rect()).adjusted(3, 3, -3, -3), 8, 8);
    for (const QPointF c : {QPointF(10, 10), QPointF(width() - 10, 10), QPointF(10, height() - 10),
                            QPointF(width() - 10, height() - 10)}) {
        QRadialGradient s(c - QPointF(1, 1), 4);
        s.setColorAt(0, QColor(0xd8, 0xda, 0xdc));
        s.setColorAt(1, QColor(0x5a, 0x5e, 0x62));
        p.setPen(QPen(QColor(0x22, 0x24, 0x26), 0.8));
        p.setBrush(s);
        p.drawEllipse(c, 3.5, 3.5);
        p.drawLine(c - QPointF(2.2, 0), c + QPointF(2.2, 0));
    }
}

} // namespace k528::studio
