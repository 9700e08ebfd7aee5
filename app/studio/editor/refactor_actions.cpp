#include "editor/refactor_actions.h"

#include "editor/editor_tab.h"
#include "editor/program_editor.h"
#include "editor/text_refactor.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialog>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QSpinBox>

namespace k528::studio {

RefactorActions::RefactorActions(EditorTab& tab) : QObject(&tab), tab_(tab) {}

void RefactorActions::replaceText(ProgramEditor* ed, const QString& text) {
    int line = 0, index = 0;
    ed->getCursorPosition(&line, &index);
    const int first = ed->firstVisibleLine();
    const QByteArray bytes = text.toUtf8();
    ed->beginUndoAction();
    ed->SendScintilla(QsciScintilla::SCI_SETTARGETSTART, 0UL);
    ed->SendScintilla(QsciScintilla::SCI_SETTARGETEND, static_cast<unsigned long>(ed->length()));
    ed->SendScintilla(QsciScintilla::SCI_REPLACETARGET, static_cast<unsigned long>(bytes.size()), bytes.constData());
    ed->endUndoAction();
    ed->setCursorPosition(std::min(line, std::max(0, ed->lines() - 1)), 0);
    ed->setFirstVisibleLine(first);
    ed->validateNow();
}

bool RefactorActions::apply(ProgramEditor* ed, const TextRefactor& r, const QString& done) {
    if (!r.ok) {
        emit statusMessage(r.error);
        return false;
    }
    if (r.text != ed->text())
        replaceText(ed, r.text);
    emit statusMessage(done);
    return true;
}

bool RefactorActions::renumber(int program, int start, int step) {
    ProgramEditor* ed = tab_.currentEditor();
    if (!ed)
        return false;
    return apply(ed, renumberText(ed->text(), program, start, step),
                 program == 0 ? tr("Renumbered every program from %1 by %2").arg(start).arg(step)
                              : tr("Renumbered L%1 from %2 by %3").arg(program).arg(start).arg(step));
}

bool RefactorActions::moveProgram(int from, int to, bool copy) {
    ProgramEditor* ed = tab_.currentEditor();
    if (!ed)
        return false;
    return apply(ed, moveProgramText(ed->text(), from, to, copy),
                 copy ? tr("Copied L%1 to L%2").arg(from).arg(to) : tr("Moved L%1 to L%2").arg(from).arg(to));
}

bool RefactorActions::formatFile() {
    ProgramEditor* ed = tab_.currentEditor();
    if (!ed)
        return false;
    return apply(ed, formatText(ed->text()), tr("Formatted"));
}

void RefactorActions::renumberDialog() {
    ProgramEditor* ed = tab_.currentEditor();
    if (!ed)
        return;
    ed->validateNow();
    QDialog d(&tab_);
    d.setObjectName("editor.renumberDialog");
    d.setWindowTitle(tr("Renumber frames"));
    auto* form = new QFormLayout(&d);
    auto* program = new QComboBox(&d);
    program->addItem(tr("Every program"), 0);
    for (const program::Program& p : ed->store().programs())
        program->addItem(QStringLiteral("L%1").arg(p.number), p.number);
    const int here = ed->programAtLine([&] {
        int line = 0, index = 0;
        ed->getCursorPosition(&line, &index);
        return line;
    }());
    if (const int at = program->findData(here); here > 0 && at >= 0)
        program->setCurrentIndex(at);
    auto* start = new QSpinBox(&d);
    start->setRange(1, program::kMaxFrameNumber);
    start->setValue(10);
    auto* step = new QSpinBox(&d);
    step->setRange(1, program::kMaxFrameNumber);
    step->setValue(10);
    form->addRow(tr("Program"), program);
    form->addRow(tr("First number"), start);
    form->addRow(tr("Step"), step);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, &d);
    form->addRow(buttons);
    connect(buttons, &QDialogButtonBox::accepted, &d, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, &d, &QDialog::reject);
    if (d.exec() == QDialog::Accepted)
        renumber(program->currentData().toInt(), start->value(), step->value());
}

void RefactorActions::moveProgramDialog() {
    ProgramEditor* ed = tab_.currentEditor();
    if (!ed)
        return;
    ed->validateNow();
    if (ed->store().empty()) {
        emit statusMessage(tr("The file has no program"));
        return;
    }
    QDialog d(&tab_);
    d.setObjectName("editor.moveDialog");
    d.setWindowTitle(tr("Move or copy a program"));
    auto* form = new QFormLayout(&d);
    auto* from = new QComboBox(&d);
    for (const program::Program& p : ed->store().programs())
        from->addItem(QStringLiteral("L%1").arg(p.number), p.number);
    auto* to = new QSpinBox(&d);
    to->setRange(1, 99);
    to->setPrefix(QStringLiteral("L"));
    int free = 1;
    while (free < 99 && ed->store().contains(free))
        ++free;
    to->setValue(free);
    auto* copy = new QCheckBox(tr("Keep the program (copy)"), &d);
    form->addRow(tr("Program"), from);
    form->addRow(tr("New number"), to);
    form->addRow(copy);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, &d);
    form->addRow(buttons);
    connect(buttons, &QDialogButtonBox::accepted, &d, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, &d, &QDialog::reject);
    if (d.exec() == QDialog::Accepted)
        moveProgram(from->currentData().toInt(), to->value(), copy->isChecked());
}

} // namespace k528::studio
