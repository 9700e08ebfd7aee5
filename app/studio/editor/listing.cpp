#include "editor/listing.h"
#include "session/file_problem.h"

#include "language.h"
#include "session/diagnostic_texts.h"

#include <QCoreApplication>
#include <QFile>
#include <QFontDatabase>
#include <QFontMetrics>
#include <QPageLayout>
#include <QPageSize>
#include <QPagedPaintDevice>
#include <QPainter>
#include <QPdfWriter>
#include <algorithm>
#include <map>

namespace k528::studio {

namespace {

// lupdate files a free tr() of namespace k528::studio under this context:
// the run time must ask for the same (it asked for its own and got English).
constexpr const char* kTrContext = "k528::studio";
QString tr(const char* s) { return QCoreApplication::translate(kTrContext, s); }

constexpr int kNumberWidth = 6; // "  123 " before each line

} // namespace

std::vector<ListingRow> listingRows(const QString& text, const std::vector<program::Diagnostic>& diagnostics) {
    std::multimap<int, const program::Diagnostic*> byLine;
    for (const program::Diagnostic& d : diagnostics)
        byLine.emplace(d.line, &d);
    QStringList lines = text.split('\n');
    if (!lines.isEmpty() && lines.last().isEmpty())
        lines.removeLast(); // the text's last line end
    std::vector<ListingRow> rows;
    rows.reserve(static_cast<std::size_t>(lines.size()) + diagnostics.size());
    auto addDiagnostics = [&](int line) {
        const auto [b, e] = byLine.equal_range(line);
        for (auto it = b; it != e; ++it) {
            const program::Diagnostic& d = *it->second;
            QString t = QString(std::max(0, d.column - 1), QChar(' ')) + QStringLiteral("^ ") +
                        (d.isError() ? tr("error") : tr("warning")) + QChar(' ') + diagnosticWithManual(d);
            rows.push_back({0, t, d.isError()});
        }
    };
    addDiagnostics(0); // about the file as a whole
    for (int i = 0; i < lines.size(); ++i) {
        QString l = lines.at(i);
        if (l.endsWith('\r'))
            l.chop(1);
        rows.push_back({i + 1, l, false});
        addDiagnostics(i + 1);
    }
    // Diagnostics past the last line (the end of the text).
    for (auto it = byLine.upper_bound(static_cast<int>(lines.size())); it != byLine.end();
         it = byLine.upper_bound(it->first))
        addDiagnostics(it->first);
    return rows;
}

QStringList listingHeader(const ListingInfo& info, const std::vector<program::Diagnostic>& diagnostics, int page,
                          int pages) {
    const std::size_t errors = program::countErrors(diagnostics);
    const QString machine = info.machine.isEmpty() ? tr("none (the language only)") : info.machine;
    return {tr("File: %1").arg(info.file),
            tr("Machine: %1    Date: %2").arg(machine, info.date.toString(QStringLiteral("yyyy-MM-dd HH:mm"))),
            tr("Errors: %1, warnings: %2    Page %3 of %4")
                .arg(errors)
                .arg(diagnostics.size() - errors)
                .arg(page)
                .arg(pages)};
}

int printListing(const QString& text, const std::vector<program::Diagnostic>& diagnostics, const ListingInfo& info,
                 QPagedPaintDevice& device) {
    const std::vector<ListingRow> rows = listingRows(text, diagnostics);
    QPainter p;
    if (!p.begin(&device))
        return 0;
    QFont mono = QFontDatabase::systemFont(QFontDatabase::FixedFont);
    mono.setPointSizeF(8.5);
    QFont bold = mono;
    bold.setBold(true);
    p.setFont(mono);
    const QFontMetrics fm(mono, &device);
    const int lineHeight = fm.lineSpacing();
    const QRect area(0, 0, device.width(), device.height());
    const int headerLines = 3;
    const int headerHeight = lineHeight * (headerLines + 1);
    const int perPage = std::max(1, (area.height() - headerHeight) / lineHeight);
    const int pages = std::max(1, static_cast<int>((rows.size() + static_cast<std::size_t>(perPage) - 1) /
                                                   static_cast<std::size_t>(perPage)));
    const int numberWidth = fm.horizontalAdvance(QString(kNumberWidth, QChar('0')));
    std::size_t at = 0;
    for (int page = 1; page <= pages; ++page) {
        if (page > 1 && !device.newPage()) {
            p.end();
            return 0;
        }
        int y = fm.ascent();
        p.setFont(bold);
        p.setPen(Qt::black);
        for (const QString& h : listingHeader(info, diagnostics, page, pages)) {
            p.drawText(0, y, fm.elidedText(h, Qt::ElideRight, area.width()));
            y += lineHeight;
        }
        p.setPen(QPen(Qt::gray, 0));
        p.drawLine(0, y - fm.ascent() + lineHeight / 2, area.width(), y - fm.ascent() + lineHeight / 2);
        y += lineHeight;
        p.setFont(mono);
        for (int n = 0; n < perPage && at < rows.size(); ++n, ++at) {
            const ListingRow& r = rows[at];
            if (r.line > 0) {
                p.setPen(QColor(0x80, 0x80, 0x80));
                p.drawText(0, y, QStringLiteral("%1").arg(r.line, kNumberWidth - 1));
                p.setPen(Qt::black);
            } else {
                p.setPen(r.error ? QColor(0xc0, 0x00, 0x00) : QColor(0xa0, 0x60, 0x00));
            }
            p.drawText(numberWidth, y, fm.elidedText(r.text, Qt::ElideRight, area.width() - numberWidth));
            y += lineHeight;
        }
    }
    p.end();
    return pages;
}

int exportListingPdf(const QString& text, const std::vector<program::Diagnostic>& diagnostics,
                     const ListingInfo& info, const QString& path, QString* error) {
    SaveFile f(path); // a listing that is not written whole leaves the file as it was
    const auto cannot = [&] {
        if (error)
            *error = tr("%1 cannot be written: %2").arg(path, fileProblem(f));
        return 0;
    };
    if (!f.open(QIODevice::WriteOnly))
        return cannot();
    int pages = 0;
    {
        QPdfWriter pdf(&f);
        pdf.setResolution(300);
        pdf.setPageLayout(QPageLayout(QPageSize(QPageSize::A4), QPageLayout::Portrait, QMarginsF(15, 12, 12, 12),
                                      QPageLayout::Millimeter));
        pdf.setTitle(info.file);
        pdf.setCreator(QStringLiteral("K528 Studio"));
        pages = printListing(text, diagnostics, info, pdf);
    }
    if (pages == 0) {
        f.cancelWriting();
        if (error)
            *error = tr("%1 cannot be written").arg(path);
        return 0;
    }
    if (!f.commit())
        return cannot();
    return pages;
}

} // namespace k528::studio
