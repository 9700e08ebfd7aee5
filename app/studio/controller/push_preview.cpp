#include "controller/push_preview.h"

#include "link/register_map.h"
#include "profile/diff.h"
#include "program/formatter.h"
#include "program/parser.h"

#include <QCoreApplication>
#include <QDialog>
#include <QDialogButtonBox>
#include <QLabel>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QVBoxLayout>

namespace k528::studio {

namespace {

// A program's text as the controller keeps it (its canonical form).
std::string canonical(int number, const std::string& text) {
    program::ParseOptions po;
    po.programNumber = number;
    const program::ParseResult r = program::parse(text, po);
    if (r.store.size() != 1)
        return text;
    program::ProgramStore one;
    one.insert(r.store.programs()[0]);
    return program::format(one);
}

QString fromStd(const std::string& s) { return QString::fromUtf8(s.data(), static_cast<qsizetype>(s.size())); }

QString said(const char* text) { return QCoreApplication::translate("k528::studio::PushPreview", text); }

} // namespace

QString diffText(const std::vector<profile::Change>& changes) {
    QString out;
    for (const profile::Change& c : changes) {
        QString key = fromStd(c.key);
        if (c.section == profile::DiffSection::Machine)
            key = c.key == "name" ? said(QT_TRANSLATE_NOOP("k528::studio::PushPreview", "name")) : c.key == "title" ? said(QT_TRANSLATE_NOOP("k528::studio::PushPreview", "title")) : key;
        QString line = key;
        if (!c.label.empty())
            line += QLatin1Char(' ') + fromStd(c.label);
        if (c.section == profile::DiffSection::Program) {
            out += line + QStringLiteral(": ") +
                   (!c.before ? said(QT_TRANSLATE_NOOP("k528::studio::PushPreview", "added")) : !c.after ? said(QT_TRANSLATE_NOOP("k528::studio::PushPreview", "removed")) : said(QT_TRANSLATE_NOOP("k528::studio::PushPreview", "changed"))) + QLatin1Char('\n');
            const QStringList lines =
                fromStd(profile::lineDiff(c.before.value_or(""), c.after.value_or(""))).split(QLatin1Char('\n'), Qt::SkipEmptyParts);
            for (const QString& l : lines)
                if (!l.startsWith(QLatin1String("  ")) || !c.before || !c.after)
                    out += QStringLiteral("    ") + l + QLatin1Char('\n');
            continue;
        }
        const QString none = said(QT_TRANSLATE_NOOP("k528::studio::PushPreview", "(none)"));
        out += line + QStringLiteral(": ") + (c.before ? fromStd(*c.before) : none) + QStringLiteral(" -> ") +
               (c.after ? fromStd(*c.after) : none) + QLatin1Char('\n');
    }
    return out;
}

profile::MachineProfile afterPush(const profile::MachineProfile& memory, const profile::MachineProfile& file) {
    profile::MachineProfile m = memory;
    m.c = file.c;
    for (int i = 0; i < 300; ++i) {
        if (!link::k528Map().rWritable(i))
            continue;
        const auto it = file.r.find(i);
        if (it != file.r.end() && it->second != 0)
            m.r[i] = it->second;
        else
            m.r.erase(i);
    }
    if (!file.messages.empty())
        m.messages = file.messages;
    for (const auto& [n, text] : file.programs)
        m.programs[n] = canonical(n, text);
    return m;
}

profile::MachineProfile afterPrograms(const profile::MachineProfile& memory, const std::string& text) {
    profile::MachineProfile m = memory;
    const program::ParseResult r = program::parse(text);
    for (const program::Program& p : r.store.programs()) {
        program::ProgramStore one;
        one.insert(p);
        m.programs[p.number] = program::format(one);
    }
    if (r.store.messages.present) {
        m.messages.clear();
        for (const program::Message& e : r.store.messages.entries)
            m.messages[e.number] = e.text;
    }
    return m;
}

QDialog* showPushPreview(QWidget* parent, const QString& what, const profile::MachineProfile& before,
                         const profile::MachineProfile& after, const QString& sendText,
                         std::function<void(bool)> done) {
    const std::vector<profile::Change> changes = profile::diff(before, after);
    auto* d = new QDialog(parent);
    d->setObjectName("controller.pushPreview");
    d->setAttribute(Qt::WA_DeleteOnClose);
    d->setWindowTitle(QDialog::tr("%1 to the controller").arg(what));
    auto* lay = new QVBoxLayout(d);
    auto* head = new QLabel(changes.empty()
                                ? QDialog::tr("The controller already holds what %1 has: nothing changes.").arg(what)
                                : QDialog::tr("Changes in the controller's memory: %1. Each part is committed all or "
                                              "nothing and read back; a controller on the line must be in F7 "
                                              "«РАБОТА С ПЭВМ».")
                                      .arg(changes.size()),
                            d);
    head->setObjectName("controller.pushPreview.head");
    head->setWordWrap(true);
    lay->addWidget(head);
    auto* text = new QPlainTextEdit(d);
    text->setObjectName("controller.pushPreview.diff");
    text->setReadOnly(true);
    text->setFont(QFont("DejaVu Sans Mono"));
    text->setPlainText(diffText(changes));
    lay->addWidget(text, 1);
    auto* box = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, d);
    box->button(QDialogButtonBox::Ok)->setText(sendText);
    lay->addWidget(box);
    QObject::connect(box, &QDialogButtonBox::accepted, d, &QDialog::accept);
    QObject::connect(box, &QDialogButtonBox::rejected, d, &QDialog::reject);
    QObject::connect(d, &QDialog::finished, d, [done](int result) { done(result == QDialog::Accepted); });
    d->resize(640, 480);
    d->open();
    return d;
}

} // namespace k528::studio
