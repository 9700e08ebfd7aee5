#include "sheet/sheet_render.h"
#include "session/save_file.h"

#include <QFont>
#include <QAbstractTextDocumentLayout>
#include <QPageLayout>
#include <QPageSize>
#include <QPdfWriter>
#include <QSaveFile>
#include <QTextDocument>

#include <utility>

namespace k528::studio {

namespace {

using proveout::SheetText;

QString q(std::string_view s) { return QString::fromUtf8(s.data(), static_cast<qsizetype>(s.size())); }
QString esc(const QString& s) { return s.toHtmlEscaped(); }

QString mm(double v, int decimals = 3) { return q(proveout::sheetMm(v, decimals)); }

QString seconds(double s) {
    const int total = static_cast<int>(s + 0.5);
    QString t = QString::number(s, 'f', 1);
    if (total >= 60)
        t += QStringLiteral(" (%1:%2)").arg(total / 60).arg(total % 60, 2, 10, QLatin1Char('0'));
    return t;
}

} // namespace

QString setupSheetHtml(const proveout::SetupSheet& s, bool ru) {
    const auto T = [ru](SheetText t) { return esc(q(proveout::sheetText(t, ru))); };
    const auto th = [](const QString& h, int widthPercent) {
        return QStringLiteral("<th align=\"left\" bgcolor=\"#e8e8e8\" width=\"%1%\">").arg(widthPercent) + h +
               QStringLiteral("</th>");
    };
    const auto td = [](const QString& c, bool right = false) {
        return QStringLiteral("<td valign=\"top\"%1>").arg(right ? QStringLiteral(" align=\"right\"") : QString()) + c +
               QStringLiteral("</td>");
    };
    const QString table = QStringLiteral("<table border=\"1\" cellspacing=\"0\" cellpadding=\"3\" width=\"100%\">");

    QString h = QStringLiteral("<html><body>");
    h += QStringLiteral("<h2>") + T(SheetText::Title) + QStringLiteral("</h2>");
    h += QStringLiteral("<table cellspacing=\"0\" cellpadding=\"2\">");
    const auto row = [&](SheetText label, const QString& value) {
        h += QStringLiteral("<tr><td><b>") + T(label) + QStringLiteral(":</b></td><td>") + value + QStringLiteral("</td></tr>");
    };
    QString machine = esc(q(s.machineName));
    if (const std::string& title = ru ? s.machineTitle : s.machineTitleEn; !title.empty())
        machine += QStringLiteral(" — ") + esc(q(title));
    machine += QStringLiteral("; ") + T(s.xDiameter ? SheetText::XDiameterNote : SheetText::XRadiusNote);
    row(SheetText::Machine, machine);
    row(SheetText::File, esc(q(s.file)));
    if (s.blank) {
        const stock::Blank& b = *s.blank;
        QString blank = esc(q(proveout::sheetText(SheetText::BlankOuter, ru)))
                            .arg(mm(b.outerDiameterMm), mm(std::abs(b.outerLengthMm)));
        if (b.boreDiameterMm > 0)
            blank += QStringLiteral("; ") + esc(q(proveout::sheetText(SheetText::BlankBore, ru)))
                                                 .arg(mm(b.boreDiameterMm), mm(std::abs(b.boreLengthMm)));
        blank += QStringLiteral(" <tt>") + esc(q(s.ucg)) + QStringLiteral("</tt>");
        row(SheetText::Blank, blank);
    } else {
        row(SheetText::Blank, T(SheetText::NoBlank));
    }
    h += QStringLiteral("</table>");

    // The tools.
    h += QStringLiteral("<h3>") + T(SheetText::Tools) + QStringLiteral("</h3>");
    if (s.tools.empty()) {
        h += QStringLiteral("<p>") + T(SheetText::NoTools) + QStringLiteral("</p>");
    } else {
        h += table + QStringLiteral("<tr>");
        const std::pair<SheetText, int> columns[] = {
            {SheetText::Station, 9},      {SheetText::Kind, 13},    {SheetText::Name, 19},    {SheetText::TipRadius, 12},
            {SheetText::Orientation, 15}, {SheetText::OffsetR, 14}, {SheetText::OffsetX, 9},  {SheetText::OffsetZ, 9}};
        for (const auto& [c, w] : columns)
            h += th(T(c), w);
        h += QStringLiteral("</tr>");
        for (const proveout::SheetTool& t : s.tools) {
            const QString offsetR = t.tool.offsetR < 0 ? QStringLiteral("—")
                                                       : QStringLiteral("R%1, R%2").arg(t.tool.offsetR).arg(t.tool.offsetR + 1);
            h += QStringLiteral("<tr>") + td(QStringLiteral("T%1").arg(t.tool.station)) +
                 td(esc(q(proveout::toolKindText(t.tool.kind, ru)))) + td(esc(q(t.name(ru)))) +
                 td(mm(t.tool.tipRadiusMm), true) + td(esc(q(t.tool.orientation()))) + td(offsetR) +
                 td(t.tool.offsetR < 0 ? QStringLiteral("—") : mm(t.offsetXMm), true) +
                 td(t.tool.offsetR < 0 ? QStringLiteral("—") : mm(t.offsetZMm), true) + QStringLiteral("</tr>");
        }
        h += QStringLiteral("</table>");
    }

    // The programs.
    h += QStringLiteral("<h3>") + T(SheetText::Programs) + QStringLiteral("</h3>");
    h += table + QStringLiteral("<tr>") + th(T(SheetText::Program), 12) + th(T(SheetText::ProgramTitle), 63) +
         th(T(SheetText::CycleTime), 25) + QStringLiteral("</tr>");
    double total = 0;
    bool anyTime = false;
    for (const proveout::SheetProgram& p : s.programs) {
        QString time;
        if (!p.main)
            time = T(SheetText::Subprogram);
        else if (p.cycleSeconds) {
            time = esc(q(proveout::sheetText(SheetText::Seconds, ru))).arg(seconds(*p.cycleSeconds));
            total += *p.cycleSeconds;
            anyTime = true;
        } else
            time = esc(q(proveout::sheetText(SheetText::NoCycleTime, ru))).arg(esc(q(p.run)));
        h += QStringLiteral("<tr>") + td(QStringLiteral("L%1").arg(p.number)) + td(esc(q(p.title))) + td(time, true) +
             QStringLiteral("</tr>");
    }
    if (anyTime)
        h += QStringLiteral("<tr>") + td(QString()) + td(QStringLiteral("<b>") + T(SheetText::Total) + QStringLiteral("</b>")) +
             td(QStringLiteral("<b>") + esc(q(proveout::sheetText(SheetText::Seconds, ru))).arg(seconds(total)) +
                    QStringLiteral("</b>"),
                true) +
             QStringLiteral("</tr>");
    h += QStringLiteral("</table>");

    // The R presets.
    h += QStringLiteral("<h3>") + T(SheetText::Presets) + QStringLiteral("</h3>");
    if (s.presets.empty()) {
        h += QStringLiteral("<p>") + T(SheetText::NoPresets) + QStringLiteral("</p>");
    } else {
        h += table + QStringLiteral("<tr>") + th(T(SheetText::Parameter), 12) + th(T(SheetText::Value), 16) +
             th(T(SheetText::ValueMm), 14) + th(T(SheetText::Meaning), 58) + QStringLiteral("</tr>");
        for (const proveout::SheetPreset& p : s.presets) {
            QString meaning = esc(q(ru ? p.meaningRu : p.meaningEn));
            if (meaning.isEmpty())
                meaning = T(SheetText::UserParameter);
            h += QStringLiteral("<tr>") + td(QStringLiteral("R%1").arg(p.number)) + td(QString::number(p.value), true) +
                 td(p.mm ? mm(*p.mm, 4) : QStringLiteral("—"), true) + td(meaning) + QStringLiteral("</tr>");
        }
        h += QStringLiteral("</table>");
    }

    // For the setter's and the checker's signatures.
    h += QStringLiteral("<p><br>") + T(SheetText::Setter) + QStringLiteral(": ____________________ &nbsp; ") +
         T(SheetText::Checked) + QStringLiteral(": ____________________ &nbsp; ") + T(SheetText::Date) +
         QStringLiteral(": ____________</p>");
    h += QStringLiteral("</body></html>");
    return h;
}

int printSetupSheet(const proveout::SetupSheet& sheet, bool russian, QPagedPaintDevice& device) {
    QTextDocument doc;
    // Laid out on the device itself, its printable area one page: the whole
    // width between the margins the device has (not QTextDocument::print's
    // own 2 cm on top of them).
    doc.documentLayout()->setPaintDevice(&device);
    doc.setPageSize(device.pageLayout().paintRectPixels(device.logicalDpiX()).size());
    doc.setDocumentMargin(0);
    QFont font(QStringLiteral("DejaVu Sans"));
    font.setPointSizeF(9);
    doc.setDefaultFont(font);
    doc.setHtml(setupSheetHtml(sheet, russian));
    doc.print(&device);
    return doc.pageCount();
}

QString writeSetupSheetPdf(const proveout::SetupSheet& sheet, bool russian, const QString& path) {
    SaveFile f(path);
    if (!f.open(QIODevice::WriteOnly))
        return q(util::systemText(f.reason(), russian));
    {
        QPdfWriter writer(&f);
        writer.setPageSize(QPageSize(QPageSize::A4));
        writer.setPageOrientation(QPageLayout::Portrait);
        writer.setPageMargins(QMarginsF(12, 12, 12, 12), QPageLayout::Millimeter);
        writer.setResolution(300);
        writer.setTitle(q(proveout::sheetText(SheetText::Title, russian)) + QStringLiteral(": ") + q(sheet.file));
        writer.setCreator(QStringLiteral("K528 Studio"));
        printSetupSheet(sheet, russian, writer);
    }
    if (!f.commit())
        return q(util::systemText(f.reason(), russian));
    return {};
}

} // namespace k528::studio
