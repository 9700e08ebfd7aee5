#include "editor/frame_master.h"

#include "language.h"
#include "session/diagnostic_texts.h"
#include "program/formatter.h"
#include "program/parser.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QRegularExpression>
#include <QStackedWidget>
#include <QVBoxLayout>

namespace k528::studio {

namespace {

using namespace program;

// "" = absent; "R12" = an R-parameter; else a decimal (nullopt + error when not one).
struct Parsed {
    bool present = false;
    bool ok = true;
    Value value;
};

Parsed parseValue(const QString& s) {
    Parsed p;
    const QString t = s.trimmed();
    if (t.isEmpty())
        return p;
    p.present = true;
    if (t.startsWith('R', Qt::CaseInsensitive)) {
        bool ok = false;
        const int r = t.mid(1).toInt(&ok);
        p.ok = ok;
        p.value = Value::rParam(r);
        return p;
    }
    const auto d = Decimal::parse(t.toStdString());
    p.ok = d.has_value();
    if (d)
        p.value = Value::lit(*d);
    return p;
}

bool parseOperand(const QString& s, Operand& o) {
    const QString t = s.trimmed();
    bool ok = false;
    if (t.startsWith('R', Qt::CaseInsensitive)) {
        o = Operand::rParam(t.mid(1).toInt(&ok));
        return ok;
    }
    const long long v = t.toLongLong(&ok);
    if (!ok || v < INT32_MIN || v > INT32_MAX)
        return false;
    o = Operand::lit(static_cast<std::int32_t>(v));
    return true;
}

std::vector<int> parseList(const QString& s, bool& ok) {
    std::vector<int> out;
    ok = true;
    for (const QString& part : s.split(QRegularExpression("[\\s,]+"), Qt::SkipEmptyParts)) {
        QString p = part;
        if (p.startsWith('G', Qt::CaseInsensitive) || p.startsWith('M', Qt::CaseInsensitive))
            p = p.mid(1);
        bool one = false;
        out.push_back(p.toInt(&one));
        ok &= one;
    }
    return out;
}

int parseInt(const QString& s, bool& ok, int absent = 0) {
    if (s.trimmed().isEmpty()) {
        ok = true;
        return absent;
    }
    return s.trimmed().toInt(&ok);
}

QString valueText(const std::optional<Value>& v) {
    if (!v)
        return {};
    std::string s;
    appendValue(s, "", *v);
    QString q = QString::fromStdString(s);
    if (q.startsWith('='))
        q = q.mid(1);
    return q;
}

QString operandText(const Operand& o) {
    return o.isR() ? QStringLiteral("R%1").arg(o.rIndex) : QString::number(o.literal);
}

} // namespace

FrameMaster::FrameMaster(QWidget* parent) : QDialog(parent) {
    setObjectName("frameMaster");
    setWindowTitle(tr("Frame master"));
    auto* layout = new QVBoxLayout(this);
    // What OK does with the editor's text: replace a line or insert one.
    placement_ = new QLabel(this);
    placement_->setObjectName("master.placement");
    placement_->setWordWrap(true);
    placement_->setTextFormat(Qt::PlainText);
    placement_->hide();
    layout->addWidget(placement_);
    auto* top = new QFormLayout;
    kindBox_ = new QComboBox(this);
    kindBox_->setObjectName("master.kind");
    kindBox_->addItems({tr("ISO motion frame"), tr("Dwell (G4)"), tr("Subprogram call (L)"),
                        tr("Oscillation start/stop"), tr("Move until signal"), tr("Computational frame"),
                        tr("Conditional jump (IF … GOTO)"), tr("Unconditional jump (GOTO)"),
                        tr("Technological message")});
    top->addRow(tr("Kind"), kindBox_);
    skip_ = new QCheckBox(tr("Skip flag «/» (the frame is not executed)"), this);
    top->addRow(QString(), skip_);
    n_ = new QLineEdit(this);
    n_->setObjectName("master.N");
    n_->setPlaceholderText(tr("1..999, empty = none"));
    top->addRow(tr("Frame number N"), n_);
    layout->addLayout(top);

    pages_ = new QStackedWidget(this);
    auto page = [this] {
        auto* w = new QWidget(pages_);
        new QFormLayout(w);
        pages_->addWidget(w);
        return w;
    };
    QWidget* iso = page();
    addField(iso, "G");
    addField(iso, "M");
    addField(iso, "#");
    addField(iso, "L");
    addField(iso, "X");
    addField(iso, "FX");
    addField(iso, "Z");
    addField(iso, "FZ");
    QWidget* dwell = page();
    addField(dwell, "seconds");
    QWidget* call = page();
    addField(call, "program");
    addField(call, "callM");
    QWidget* osc = page();
    axis_ = new QComboBox(osc);
    axis_->addItems({"X", "Z"});
    static_cast<QFormLayout*>(osc->layout())->addRow(tr("Axis"), axis_);
    addField(osc, "start");
    addField(osc, "stroke");
    addField(osc, "speed");
    QWidget* sig = page();
    addField(sig, "sigAxis");
    addField(sig, "signal");
    addField(sig, "target");
    addField(sig, "feed");
    QWidget* comp = page();
    addField(comp, "R");
    addField(comp, "a");
    op_ = new QComboBox(comp);
    op_->addItems({QString(), "+", "-", "*", "/"});
    static_cast<QFormLayout*>(comp->layout())->addRow(tr("Operation"), op_);
    addField(comp, "b");
    QWidget* ifg = page();
    addField(ifg, "ifR");
    addField(ifg, "ifTarget");
    QWidget* go = page();
    addField(go, "gotoTarget");
    QWidget* msg = page();
    addField(msg, "msgNumber");
    addField(msg, "msgText");
    layout->addWidget(pages_);

    preview_ = new QLabel(this);
    preview_->setObjectName("master.preview");
    preview_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    QFont mono("monospace");
    mono.setStyleHint(QFont::TypeWriter);
    preview_->setFont(mono);
    problems_ = new QLabel(this);
    problems_->setObjectName("master.problems");
    problems_->setWordWrap(true);
    problems_->setStyleSheet("color: #c00000");
    layout->addWidget(preview_);
    layout->addWidget(problems_);
    buttons_ = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    layout->addWidget(buttons_);
    connect(buttons_, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons_, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(kindBox_, &QComboBox::currentIndexChanged, this, [this](int i) {
        pages_->setCurrentIndex(i);
        rebuild();
    });
    connect(skip_, &QCheckBox::toggled, this, &FrameMaster::rebuild);
    connect(n_, &QLineEdit::textChanged, this, &FrameMaster::rebuild);
    connect(axis_, &QComboBox::currentIndexChanged, this, &FrameMaster::rebuild);
    connect(op_, &QComboBox::currentIndexChanged, this, &FrameMaster::rebuild);
    rebuild();
}

QLineEdit* FrameMaster::addField(QWidget* page, const QString& name) {
    static const QHash<QString, const char*> labels = {
        {"G", QT_TR_NOOP("G-functions (up to 3)")}, {"M", QT_TR_NOOP("M-functions (up to 3)")},
        {"#", QT_TR_NOOP("Message #")}, {"L", QT_TR_NOOP("Call program L")},
        {"X", QT_TR_NOOP("X, mm (or R…)")}, {"FX", QT_TR_NOOP("FX, mm/min (or R…)")},
        {"Z", QT_TR_NOOP("Z, mm (or R…)")}, {"FZ", QT_TR_NOOP("FZ, mm/min (or R…)")},
        {"seconds", QT_TR_NOOP("Dwell, s")}, {"program", QT_TR_NOOP("Program 1..99")},
        {"callM", QT_TR_NOOP("M-functions (up to 3)")}, {"start", QT_TR_NOOP("Start (1) / stop (0)")},
        {"stroke", QT_TR_NOOP("Stroke, mm")}, {"speed", QT_TR_NOOP("Speed, mm/min")},
        {"sigAxis", QT_TR_NOOP("Axis (X or Z)")}, {"signal", QT_TR_NOOP("Signal 1..4")},
        {"target", QT_TR_NOOP("Target, mm")}, {"feed", QT_TR_NOOP("Feed, mm/min")},
        {"R", QT_TR_NOOP("Result R")}, {"a", QT_TR_NOOP("Operand 1 (number or R…)")},
        {"b", QT_TR_NOOP("Operand 2 (number or R…)")}, {"ifR", QT_TR_NOOP("Condition R (> 0)")},
        {"ifTarget", QT_TR_NOOP("Jump to frame N")}, {"gotoTarget", QT_TR_NOOP("Jump to frame N")},
        {"msgNumber", QT_TR_NOOP("Message number 1..99")}, {"msgText", QT_TR_NOOP("Text (20 characters)")},
    };
    auto* e = new QLineEdit(page);
    e->setObjectName("master." + name);
    static_cast<QFormLayout*>(page->layout())->addRow(tr(labels.value(name, "")), e);
    connect(e, &QLineEdit::textChanged, this, &FrameMaster::rebuild);
    return e;
}

QLineEdit* FrameMaster::field(const QString& name) const {
    return findChild<QLineEdit*>("master." + name);
}

void FrameMaster::setKind(Kind k) { kindBox_->setCurrentIndex(k); }
FrameMaster::Kind FrameMaster::kind() const { return static_cast<Kind>(kindBox_->currentIndex()); }

FrameHead FrameMaster::head() const {
    FrameHead h;
    h.skip = skip_->isChecked();
    bool ok = true;
    h.n = parseInt(n_->text(), ok);
    if (!ok)
        h.n = -1;
    return h;
}

QString FrameMaster::problemsText() const {
    QStringList out;
    for (const Diagnostic& d : last_)
        out << diagnosticWithManual(d);
    return out.join('\n');
}

void FrameMaster::rebuild() {
    if (!buttons_)
        return;
    auto f = [this](const char* n) { return field(QString::fromLatin1(n))->text(); };
    QStringList inputErrors;
    auto value = [&](const char* n) -> std::optional<Value> {
        const Parsed p = parseValue(f(n));
        if (!p.ok)
            inputErrors << tr("%1: «%2» is not a number or R-parameter").arg(QString::fromLatin1(n), f(n));
        return p.present && p.ok ? std::optional<Value>(p.value) : std::nullopt;
    };
    auto integer = [&](const char* n, int absent = 0) {
        bool ok = true;
        const int v = parseInt(f(n), ok, absent);
        if (!ok)
            inputErrors << tr("%1: «%2» is not a whole number").arg(QString::fromLatin1(n), f(n));
        return v;
    };
    auto decimal = [&](const char* n) {
        const auto v = value(n);
        return v && !v->isR() ? v->literal : Decimal();
    };
    const FrameHead h = head();
    if (h.n < 0)
        inputErrors << tr("N: «%1» is not a whole number").arg(n_->text());
    BuiltFrame b;
    QString text;
    last_.clear();
    switch (kind()) {
    case Iso: {
        IsoFields in;
        in.head = h;
        bool ok = true;
        in.g = parseList(f("G"), ok);
        if (!ok)
            inputErrors << tr("G: a list of numbers, e.g. «1 90»");
        in.m = parseList(f("M"), ok);
        if (!ok)
            inputErrors << tr("M: a list of numbers, e.g. «3 8»");
        in.message = integer("#");
        in.call = integer("L");
        in.x = value("X");
        in.fx = value("FX");
        in.z = value("Z");
        in.fz = value("FZ");
        b = buildIso(in);
        break;
    }
    case Dwell:
        b = buildDwell(h, decimal("seconds"));
        break;
    case Call: {
        bool ok = true;
        std::vector<int> m = parseList(f("callM"), ok);
        b = buildCall(h, integer("program"), m);
        break;
    }
    case Oscillation: {
        const Axis a = axis_->currentIndex() == 1 ? Axis::Z : Axis::X;
        const bool start = integer("start", 1) != 0;
        const auto stroke = value("stroke");
        const auto speed = value("speed");
        b = buildOscillation(h, a, start, stroke ? std::optional<Decimal>(stroke->literal) : std::nullopt,
                             speed ? std::optional<Decimal>(speed->literal) : std::nullopt);
        break;
    }
    case UntilSignal: {
        const Axis a = f("sigAxis").trimmed().compare("Z", Qt::CaseInsensitive) == 0 ? Axis::Z : Axis::X;
        b = buildMoveUntilSignal(h, a, integer("signal", 1), decimal("target"), decimal("feed"));
        break;
    }
    case Compute: {
        Operand a, c;
        if (!parseOperand(f("a"), a))
            inputErrors << tr("Operand 1: a whole number or R…");
        const ArithOp op = static_cast<ArithOp>(op_->currentIndex());
        if (op != ArithOp::None && !parseOperand(f("b"), c))
            inputErrors << tr("Operand 2: a whole number or R…");
        QString r = f("R").trimmed();
        if (r.startsWith('R', Qt::CaseInsensitive))
            r = r.mid(1);
        bool ok = false;
        const int target = r.toInt(&ok);
        if (!ok)
            inputErrors << tr("Result: the number of the R-parameter written");
        b = buildCompute(h, target, a, op, c);
        break;
    }
    case IfGoto: {
        QString r = f("ifR").trimmed();
        if (r.startsWith('R', Qt::CaseInsensitive))
            r = r.mid(1);
        bool ok = false;
        const int ri = r.toInt(&ok);
        if (!ok)
            inputErrors << tr("R: the number of the R-parameter tested");
        b = buildIfGoto(h, ri, integer("ifTarget"));
        break;
    }
    case Goto:
        b = buildGoto(h, integer("gotoTarget"));
        break;
    case Message: {
        const BuiltMessage m = buildMessage(integer("msgNumber"), f("msgText").toStdString());
        text = QString::fromStdString(m.text);
        last_ = m.problems;
        break;
    }
    default:
        break;
    }
    if (kind() != Message) {
        text = QString::fromStdString(b.text);
        last_ = b.problems;
    }
    text_ = text;
    valid_ = inputErrors.isEmpty() && !hasErrors(last_);
    preview_->setText(text_);
    QString p = inputErrors.join('\n');
    const QString rules = problemsText();
    if (!rules.isEmpty())
        p += (p.isEmpty() ? QString() : QStringLiteral("\n")) + rules;
    problems_->setText(p);
    buttons_->button(QDialogButtonBox::Ok)->setEnabled(valid_);
}

void FrameMaster::setPlacement(const QString& text) {
    placement_->setText(text);
    placement_->setVisible(!text.isEmpty());
}

QString FrameMaster::placement() const { return placement_->text(); }

bool FrameMaster::setFromLine(const QString& line) {
    const std::string s = line.toStdString();
    const QString t = line.trimmed();
    if (t.startsWith('#') && t.contains('=')) {
        const ParseResult r = parse("%MESSAGES\n" + s + "\n");
        if (r.store.messages.entries.empty())
            return false;
        const program::Message& m = r.store.messages.entries.front();
        setKind(Message);
        field("msgNumber")->setText(QString::number(m.number));
        field("msgText")->setText(QString::fromStdString(m.text));
        return true;
    }
    const ParseResult r = parse("%L1\n" + s + "\n");
    if (r.store.empty() || r.store.programs()[0].frames.size() != 1)
        return false;
    const Frame& fr = r.store.programs()[0].frames[0];
    skip_->setChecked(fr.skip);
    n_->setText(fr.n ? QString::number(fr.n->number) : QString());
    if (const auto iso = fr.iso()) {
        QStringList g, m;
        for (const Word& w : iso->g)
            g << QString::number(w.number);
        for (const Word& w : iso->m)
            m << QString::number(w.number);
        const bool onlyDwell = g == QStringList{"4"} && m.isEmpty() && !iso->z && !iso->fx && !iso->fz &&
                               !iso->call && !iso->message && iso->x && !iso->x->isR();
        const bool onlyCall = g.isEmpty() && iso->call && !iso->x && !iso->z && !iso->fx && !iso->fz &&
                              !iso->message;
        if (onlyDwell) {
            setKind(Dwell);
            field("seconds")->setText(valueText(iso->x));
        } else if (onlyCall) {
            setKind(Call);
            field("program")->setText(QString::number(iso->call->number));
            field("callM")->setText(m.join(' '));
        } else {
            setKind(Iso);
            field("G")->setText(g.join(' '));
            field("M")->setText(m.join(' '));
            field("#")->setText(iso->message ? QString::number(iso->message->number) : QString());
            field("L")->setText(iso->call ? QString::number(iso->call->number) : QString());
            field("X")->setText(valueText(iso->x));
            field("FX")->setText(valueText(iso->fx));
            field("Z")->setText(valueText(iso->z));
            field("FZ")->setText(valueText(iso->fz));
        }
    } else if (const auto c = fr.compute()) {
        setKind(Compute);
        field("R")->setText(QStringLiteral("R%1").arg(c->target.number));
        field("a")->setText(operandText(c->a));
        op_->setCurrentIndex(static_cast<int>(c->op));
        field("b")->setText(c->op != ArithOp::None ? operandText(c->b) : QString());
    } else if (const auto j = fr.ifGoto()) {
        setKind(IfGoto);
        field("ifR")->setText(QStringLiteral("R%1").arg(j->r.number));
        field("ifTarget")->setText(QString::number(j->target.number));
    } else if (const auto g = fr.gotoFrame()) {
        setKind(Goto);
        field("gotoTarget")->setText(QString::number(g->target.number));
    }
    rebuild();
    return true;
}

} // namespace k528::studio
