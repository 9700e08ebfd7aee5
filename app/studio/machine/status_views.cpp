#include "machine/status_views.h"
#include "workspace/elided_label.h"

#include "engine/interface_words.h"
#include "session/catalog_texts.h"
#include "controller/controller.h"
#include "profile/english.h"
#include "window_language.h"

#include <QEvent>
#include <QHeaderView>
#include <QLabel>
#include <QTableWidget>
#include <QTreeWidget>
#include <QVBoxLayout>
#include <cmath>

namespace k528::studio {

namespace z = engine::z;

namespace {

QString fromStd(const std::string& s) {
    return QString::fromUtf8(s.data(), static_cast<qsizetype>(s.size()));
}

QString dot(bool on, const char* color = "#2fbf4f") {
    return QStringLiteral("<span style='color:%1;font-size:13px'>●</span>")
        .arg(on ? QString::fromLatin1(color) : QStringLiteral("#b9bdc1"));
}

} // namespace

// ---------------------------------------------------------------------------
// MessagesView

MessagesView::MessagesView(Controller& controller, QWidget* parent)
    : QWidget(parent), controller_(&controller) {
    setObjectName("messagesView");
    auto* lay = new QVBoxLayout(this);
    lay->setContentsMargins(4, 4, 4, 4);
    summary_ = new ElidedLabel(this); // cut rather than widen the window
    summary_->setObjectName("messages.summary");
    lay->addWidget(summary_);
    list_ = new QTreeWidget(this);
    list_->setObjectName("messages.list");
    list_->setRootIsDecorated(false);
    list_->setColumnCount(4);
    list_->setAlternatingRowColors(true);
    list_->setUniformRowHeights(true);
    list_->header()->setStretchLastSection(false);
    list_->header()->setSectionResizeMode(2, QHeaderView::Stretch);
    lay->addWidget(list_);
    retranslate();
    connect(controller_, &Controller::updated, this, &MessagesView::refresh);
    refresh();
}

void MessagesView::setController(Controller& controller) {
    if (controller_ == &controller)
        return;
    disconnect(controller_, nullptr, this, nullptr);
    controller_ = &controller;
    connect(controller_, &Controller::updated, this, &MessagesView::refresh);
    retranslate();
}

void MessagesView::retranslate() {
    list_->setHeaderLabels({tr("Source"), tr("No."), tr("Message"), tr("State")});
    last_.clear();
    refresh();
}

void MessagesView::changeEvent(QEvent* e) {
    if (e->type() == QEvent::LanguageChange)
        retranslate();
    QWidget::changeEvent(e);
}

void MessagesView::refresh() {
    const ControllerState& st = controller_->state();
    struct Row {
        QString source, number, text, state;
        QColor color;
    };
    std::vector<Row> rows;
    const QColor red(0xb0, 0x1c, 0x1c), orange(0xb8, 0x62, 0x00), blue(0x1d, 0x4f, 0x91),
        grey(0x55, 0x5a, 0x60);
    for (const engine::AlarmView& a : st.alarms) {
        QString text = alarmMessage(a);
        if (a.program > 0)
            text += tr(" (L%1, line %2)").arg(a.program).arg(a.line);
        const QColor c = a.category == engine::AlarmCategory::System ? orange : red;
        rows.push_back({tr("Positioner"), QString::number(a.number), text,
                        a.active ? tr("active") : tr("waits for acknowledgement"), c});
    }
    const engine::PlcMessagesView pm = st.plcMessages;
    const profile::MachineProfile& prof = controller_->profile();
    // The machine file's text in the window's language (its English when it gives one).
    const auto text = [&](const std::map<int, std::string>& texts, catalog::PlcGroup g, int k) {
        return texts.contains(k) ? coreText(profile::plcText(prof, g, k, false), profile::plcText(prof, g, k, true))
                                 : fromStd(catalog::plcMessageAddress(g, k));
    };
    for (int k = 1; k <= 16; ++k)
        if ((pm.system >> (k - 1)) & 1u)
            rows.push_back({tr("PLC system"), QStringLiteral("S%1").arg(k, 2, 10, QChar('0')),
                            text(prof.plcSystem, catalog::PlcGroup::System, k),
                            ((pm.systemPresent >> (k - 1)) & 1u) ? tr("active")
                                                                 : tr("waits for acknowledgement"),
                            orange});
    for (int k = 1; k <= 32; ++k)
        if ((pm.alarms >> (k - 1)) & 1u)
            rows.push_back({tr("PLC alarm"), QStringLiteral("A%1").arg(k, 2, 10, QChar('0')),
                            text(prof.plcAlarm, catalog::PlcGroup::Alarm, k),
                            ((pm.alarmsPresent >> (k - 1)) & 1u) ? tr("active")
                                                                 : tr("waits for acknowledgement"),
                            red});
    for (int k = 1; k <= 32; ++k)
        if ((pm.work >> (k - 1)) & 1u)
            rows.push_back({tr("PLC"), QStringLiteral("W%1").arg(k, 2, 10, QChar('0')),
                            text(prof.plcWork, catalog::PlcGroup::Work, k), tr("information"),
                            blue});
    const engine::ProgramView& pv = st.program;
    if (pv.messageNumber > 0) {
        const QString message = coreText(engine::programMessageText(pv, prof, false),
                                         engine::programMessageText(pv, prof, true));
        rows.push_back({tr("Program"), QStringLiteral("#%1").arg(pv.messageNumber), message,
                        tr("information"), grey});
    }

    std::vector<QString> sig;
    for (const Row& r : rows)
        sig.push_back(r.source + '|' + r.number + '|' + r.text + '|' + r.state);
    if (sig == last_)
        return;
    last_ = std::move(sig);
    list_->clear();
    int alarms = 0;
    for (const Row& r : rows) {
        auto* item = new QTreeWidgetItem(list_, {r.source, r.number, r.text, r.state});
        for (int c = 0; c < 4; ++c)
            item->setForeground(c, r.color);
        if (r.color == red || r.color == orange)
            ++alarms;
    }
    for (int c : {0, 1, 3})
        list_->resizeColumnToContents(c);
    summary_->setText(alarms == 0 ? tr("No alarms.")
                                  : tr("Alarms: %1. Acknowledge with RESET on the machine panel "
                                       "or ESC on the K923 once the cause is gone.")
                                        .arg(alarms));
}

// ---------------------------------------------------------------------------
// AxesView

AxesView::AxesView(Controller& controller, QWidget* parent)
    : QWidget(parent), controller_(&controller) {
    setObjectName("axesView");
    auto* lay = new QVBoxLayout(this);
    lay->setContentsMargins(4, 4, 4, 4);
    table_ = new QTableWidget(2, 9, this);
    table_->setObjectName("axes.table");
    table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
    table_->setSelectionMode(QAbstractItemView::NoSelection);
    table_->verticalHeader()->setVisible(false);
    table_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    table_->horizontalHeader()->setStretchLastSection(true);
    table_->setFocusPolicy(Qt::NoFocus);
    QFont mono("DejaVu Sans Mono");
    mono.setStyleHint(QFont::Monospace);
    table_->setFont(mono);
    for (int r = 0; r < 2; ++r)
        for (int c = 0; c < 9; ++c) {
            auto* it = new QTableWidgetItem;
            it->setTextAlignment(c == 0 || c == 8 ? Qt::AlignLeft | Qt::AlignVCenter
                                                  : Qt::AlignRight | Qt::AlignVCenter);
            table_->setItem(r, c, it);
        }
    table_->setVerticalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    table_->setSizeAdjustPolicy(QAbstractScrollArea::AdjustToContents);
    table_->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
    lay->addWidget(table_);
    bits_ = new QLabel(this);
    bits_->setObjectName("axes.bits");
    bits_->setTextFormat(Qt::RichText);
    bits_->setAlignment(Qt::AlignTop | Qt::AlignLeft);
    lay->addWidget(bits_, 1);
    retranslate();
    connect(controller_, &Controller::updated, this, &AxesView::refresh);
}

void AxesView::setController(Controller& controller) {
    if (controller_ == &controller)
        return;
    disconnect(controller_, nullptr, this, nullptr);
    controller_ = &controller;
    connect(controller_, &Controller::updated, this, &AxesView::refresh);
    retranslate();
}

void AxesView::retranslate() {
    table_->setHorizontalHeaderLabels({tr("Axis"), tr("Current, mm"), tr("Machine, mm"),
                                       tr("Rest, mm"), tr("Feed, mm/min"), tr("Error, µm"),
                                       tr("DAC"), tr("Volts"), tr("State")});
    lastBits_.clear();
    refresh();
}

void AxesView::changeEvent(QEvent* e) {
    if (e->type() == QEvent::LanguageChange)
        retranslate();
    QWidget::changeEvent(e);
}

void AxesView::refresh() {
    const ControllerState& cs = controller_->state();
    for (int i = 0; i < 2; ++i) {
        const engine::AxisView& v = cs.axes[static_cast<std::size_t>(i)];
        const auto set = [&](int c, const QString& s) {
            if (table_->item(i, c)->text() != s)
                table_->item(i, c)->setText(s);
        };
        set(0, QString(i == 0 ? "X" : "Z") + (v.scale.diameter ? tr(" (dia.)") : QString()));
        if (!v.present) {
            for (int c = 1; c < 9; ++c)
                set(c, c == 8 ? tr("absent") : QString());
            continue;
        }
        set(1, fromStd(units::formatDisc(v.currentDisc, v.scale)));
        set(2, fromStd(units::formatDisc(v.machineDisc, v.scale)));
        // The link's map has no rest of path, feed or DAC: blank, not 0.
        set(3, cs.hasServoData ? fromStd(units::formatDisc(v.remainingDisc, v.scale)) : QString());
        set(4, cs.hasServoData
                   ? QString::number(static_cast<double>(v.feedDiscPerMin) * v.scale.discreteMm(), 'f', 1)
                   : QString());
        // Internal units: half a discrete of motion; µm of the displayed value.
        const double errUm = v.errorInternal / static_cast<double>(v.scale.internalPerDisc()) *
                             v.scale.discreteMm() * 1000.0;
        set(5, QString::number(errUm, 'f', 1));
        set(6, cs.hasServoData ? QString::number(v.dac) : QString());
        set(7, cs.hasServoData ? QString::number(v.dac / 204.8, 'f', 2) : QString());
        QStringList st;
        if (v.homing)
            st << tr("homing");
        else if (v.referenced)
            st << tr("homed");
        else
            st << tr("not homed");
        st << (v.loopClosed ? tr("loop closed") : tr("loop open"));
        if (v.moving)
            st << tr("moving");
        else if (v.inPosition)
            st << tr("in position");
        // The switches as the controller sees its inputs.
        if (v.decelCam)
            st << tr("cam");
        if (v.limitPlus)
            st << tr("limit +");
        if (v.limitMinus)
            st << tr("limit -");
        if (v.fault)
            st << tr("fault %1").arg(v.fault);
        set(8, st.join(", "));
    }

    const engine::InterfaceWords& w = cs.words;
    const auto b = [&](engine::ZBit bit, const QString& label, const char* color = "#2fbf4f") {
        return dot(w.bit(bit), color) + QStringLiteral("&nbsp;") + label.toHtmlEscaped() +
               QStringLiteral("&nbsp;&nbsp; ");
    };
    const auto head = [](const QString& s) {
        return QStringLiteral("<tr><td style='padding-right:10px'><b>%1</b></td><td>").arg(s);
    };
    QString html = QStringLiteral("<table cellspacing='2'>");
    html += head(tr("Z1000 PLC→")) + b(z::EmergencyStopOk, tr("E-stop released")) +
            b(z::FeedEnable, tr("feed enable")) + b(z::StartEnable, tr("start enable")) +
            b(z::Start, tr("start")) + b(z::Stop, tr("stop"), "#d23a2a") +
            b(z::Reset, tr("reset"), "#2d6fd0") + b(z::DataHold, tr("data hold"), "#d98a00") +
            b(z::AckFaults, tr("acknowledge")) + b(z::MAcknowledge, tr("M done")) +
            tr("mode %1").arg(w.field(z::ModeCodeWord, z::ModeCodeFirst, z::ModeCodeWidth)) +
            QStringLiteral("</td></tr>");
    html += head(tr("Z2000 →PLC")) + b(z::Ready, tr("ready")) +
            b(z::ProgramRunning, tr("running")) +
            b(z::ProgramInterrupted, tr("interrupted"), "#d98a00") +
            b(z::EndOrReset, tr("end/reset"), "#2d6fd0") + b(z::DwellRunning, tr("dwell")) +
            b(z::M0Stop, tr("M00"), "#d98a00") + b(z::OverrideZero, tr("override 0%"), "#d98a00") +
            b(z::WheelChange, tr("change wheel"), "#d23a2a") + QStringLiteral("</td></tr>");
    html += head(tr("Z2001")) + b(z::MStrobe, tr("M strobe")) +
            tr("M code %1").arg(w.field(z::MCodeWord, z::MCodeFirst, z::MCodeWidth));
    for (int n = 1; n <= 8; ++n)
        if (w.bit(z::cycleRunning(n)))
            html += QStringLiteral("&nbsp;&nbsp;") + tr("cycle %1").arg(n);
    html += QStringLiteral("</td></tr>");
    for (int i = 0; i < 2; ++i) {
        const engine::AxisId a = engine::axisAt(i);
        const QString n = i == 0 ? QStringLiteral("X") : QStringLiteral("Z");
        html += head(QStringLiteral("Z%1/Z%2 %3")
                         .arg(i == 0 ? 1005 : 1008)
                         .arg(i == 0 ? 2005 : 2007)
                         .arg(n)) +
                b(z::regulatorEnable(a), tr("regulator")) + b(z::axisFeedEnable(a), tr("feed")) +
                b(z::jogPlus(a), tr("jog +")) + b(z::jogMinus(a), tr("jog -")) +
                b(z::rapid(a), tr("rapid")) + b(z::referenced(a), tr("homed"), "#2d6fd0") +
                b(z::loopClosed(a), tr("loop")) +
                b(z::positionNotReached(a), tr("moving"), "#d98a00") +
                b(z::loopError(a), tr("loop error"), "#d23a2a") + QStringLiteral("</td></tr>");
        QString fast;
        for (int k = 1; k <= 8; ++k)
            fast += dot(w.bit(z::fastInputState(a, k)), "#e0b000") + QString::number(k) +
                    QStringLiteral("&nbsp;");
        html += head(QStringLiteral("Z%1 %2").arg(i == 0 ? 2006 : 2008).arg(n)) +
                tr("fast inputs ") + fast + QStringLiteral("</td></tr>");
    }
    html += QStringLiteral("</table>");
    if (html != lastBits_) {
        bits_->setText(html);
        lastBits_ = html;
    }
}

} // namespace k528::studio
