#include "editor/teach_in.h"

#include "controller/controller.h"
#include "editing/teach.h"
#include "editor/editor_tab.h"
#include "editor/program_editor.h"
#include "window_language.h"
#include "units/units.h"

#include <QMenu>
#include <QRegularExpression>
#include <optional>

namespace k528::studio {

TeachIn::TeachIn(EditorTab& tab, ViewedController* viewed) : QObject(&tab), tab_(tab), viewed_(viewed) {}

void TeachIn::fillTargetsMenu(QMenu* menu) {
    menu->clear();
    for (const editing::TeachTarget& t : editing::teachTargets()) {
        const QString meaning = coreText(t.meaningRu, t.meaningEn);
        QAction* a = menu->addAction(QStringLiteral("R%1 — %2").arg(t.r).arg(meaning));
        a->setData(t.r);
        connect(a, &QAction::triggered, this, [this, r = t.r] { teachIntoR(r); });
    }
}

int TeachIn::frameNumberAtCursor() const {
    ProgramEditor* ed = tab_.currentEditor();
    if (!ed)
        return 0;
    int line = 0, index = 0;
    ed->getCursorPosition(&line, &index);
    static const QRegularExpression n(QStringLiteral("^\\s*/?\\s*N(\\d+)"));
    const QRegularExpressionMatch m = n.match(ed->text(line));
    return m.hasMatch() ? m.captured(1).toInt() : 0;
}

bool TeachIn::insertTaught(const QString& text, bool replaceLine) {
    const EditorTab::PlacedLine placed = tab_.placeLine(text, replaceLine);
    if (placed.line < 0)
        return false;
    ProgramEditor* ed = tab_.currentEditor();
    const QString now = ed->text(placed.line);
    ed->setCursorPosition(placed.line, static_cast<int>(now.size()) - (now.endsWith('\n') ? 1 : 0));
    ed->setFocus();
    return true;
}

bool TeachIn::teachPosition(QString* taught) {
    if (!tab_.currentEditor()) {
        emit statusMessage(tr("Open a program file in the editor to teach a position into it"));
        return false;
    }
    if (!viewed_) {
        emit statusMessage(tr("No controller is viewed: no position to teach"));
        return false;
    }
    const ControllerState& st = viewed_->current().state();
    std::optional<double> x, z;
    for (const engine::AxisView& a : st.axes) {
        if (!a.present)
            continue;
        (a.axis == engine::AxisId::X ? x : z) = units::discToMm(a.currentDisc, a.scale);
    }
    const std::string frame = editing::teachFrame(editing::nextFrameNumber(frameNumberAtCursor()), x, z);
    if (frame.empty()) {
        emit statusMessage(tr("The viewed controller has no axes: no position to teach"));
        return false;
    }
    const QString text = QString::fromStdString(frame);
    insertTaught(text, false);
    if (taught)
        *taught = text;
    emit statusMessage(tr("Taught: %1").arg(text));
    return true;
}

bool TeachIn::teachIntoR(int r, QString* taught) {
    ProgramEditor* ed = tab_.currentEditor();
    if (!ed) {
        emit statusMessage(tr("Open a program file in the editor to teach a position into it"));
        return false;
    }
    if (!viewed_) {
        emit statusMessage(tr("No controller is viewed: no position to teach"));
        return false;
    }
    std::optional<editing::TeachTarget> target;
    for (const editing::TeachTarget& t : editing::teachTargets())
        if (t.r == r)
            target = t;
    if (!target)
        return false;
    const engine::AxisId id = target->axis == catalog::Axis::X ? engine::AxisId::X : engine::AxisId::Z;
    const engine::AxisView* axis = nullptr;
    for (const engine::AxisView& a : viewed_->current().state().axes)
        if (a.present && a.axis == id)
            axis = &a;
    if (!axis) {
        emit statusMessage(tr("The viewed controller has no axis %1").arg(id == engine::AxisId::X ? "X" : "Z"));
        return false;
    }
    const std::int64_t disc = target->machineCoordinate ? axis->machineDisc : axis->currentDisc;
    // The cursor's line sets this R already: it gets the new value, its N and comments kept.
    int line = 0, index = 0;
    ed->getCursorPosition(&line, &index);
    const QRegularExpression sets(QStringLiteral("^\\s*(/?\\s*N(\\d+)\\s*)?R0*%1\\s*=").arg(r));
    const QRegularExpressionMatch m = sets.match(ed->text(line));
    const bool replace = m.hasMatch();
    const int n = replace ? m.captured(2).toInt() : editing::nextFrameNumber(frameNumberAtCursor());
    const QString text = QString::fromStdString(editing::teachRFrame(n, r, disc));
    insertTaught(text, replace);
    if (taught)
        *taught = text;
    emit statusMessage(tr("Taught: %1 (%2 mm)").arg(text).arg(units::discToMm(disc, axis->scale), 0, 'f', 3));
    return true;
}

} // namespace k528::studio
