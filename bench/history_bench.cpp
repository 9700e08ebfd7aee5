// The message history dock: a database holding 100,000 messages
// (written here in batches as the recorder writes them), then the dock opened
// on it — the database opened, the count, the first page, the table shown —
// and a search over all of them. Offscreen Qt.
#include "report.h"

#include "db/message_log.h"
#include "history/history_dock.h"
#include "history/history_model.h"
#include "history/history_service.h"

#include <QApplication>
#include <QLineEdit>
#include <QTableView>
#include <QTemporaryDir>
#include <cstdlib>
#include <filesystem>

using namespace k528;

int main(int argc, char** argv) {
    if (!std::getenv("DISPLAY") && !std::getenv("QT_QPA_PLATFORM"))
        qputenv("QT_QPA_PLATFORM", "offscreen");
    QApplication app(argc, argv);
    const int count = argc > 1 ? std::atoi(argv[1]) : 100000;
    QTemporaryDir dir;
    dir.setAutoRemove(!std::getenv("K528_BENCH_KEEP"));
    const QString path = dir.filePath("k528.db");
    bench::Report report;
    {
        db::OpenOptions o;
        o.seedBuiltins = false;
        db::Database d = db::Database::open(std::filesystem::path(path.toStdString()), o);
        db::MessageLog log(d);
        const std::int64_t day0 = 1'800'000'000'000;
        const std::int64_t run = log.beginRun("grinder-205", day0);
        const double w0 = bench::nowSeconds();
        std::vector<db::MessageEvent> batch;
        for (int i = 1; i <= count; ++i) {
            db::MessageEvent e;
            e.seq = i;
            e.machineMs = std::int64_t{i} * 750;
            e.dayMs = day0 + e.machineMs;
            e.message.source = static_cast<db::MessageSource>(i % db::kMessageSourceCount);
            e.message.number = 1 + i % 16;
            e.message.text = "Сообщение " + std::to_string(i % 997);
            e.message.textEn = "Message " + std::to_string(i % 997);
            e.message.program = i % 3 == 0 ? 1 + i % 99 : 0;
            e.message.line = e.message.program ? 1 + i % 40 : 0;
            batch.push_back(e);
            if (i % 2 == 0) {
                db::MessageEvent a;
                a.kind = db::MessageEvent::Kind::Acknowledged;
                a.seq = i;
                a.machineMs = e.machineMs + 300;
                a.dayMs = e.dayMs + 300;
                a.how = "esc";
                batch.push_back(a);
            }
            if (batch.size() >= 5000 || i == count) {
                log.write(run, batch);
                batch.clear();
            }
        }
        report.figure("history.write_messages_per_s", count / (bench::nowSeconds() - w0),
                      "msg/s", 10000, bench::Better::Higher);
    }
    // The dock opens: its database, the count, the newest page, the table painted.
    const double t0 = bench::nowSeconds();
    studio::HistoryService service(nullptr, path);
    if (!service.isOpen()) {
        std::fprintf(stderr, "%s\n", qPrintable(service.error()));
        return 1;
    }
    studio::HistoryView view(service);
    view.resize(1200, 500);
    view.show();
    app.processEvents();
    view.table()->viewport()->repaint();
    const double opened = bench::nowSeconds() - t0;
    const std::int64_t total = view.model()->total();
    report.figure("history.messages_in_the_dock", static_cast<double>(total), "messages", count,
                  bench::Better::Higher);
    report.figure("history.dock_opens_100000_messages", opened, "s", 0.5, bench::Better::Lower);
    // A search over all of them.
    const double s0 = bench::nowSeconds();
    view.searchBox()->setText("Message 996");
    view.applyFilter();
    app.processEvents();
    report.figure("history.search_100000_messages", bench::nowSeconds() - s0, "s", 0.5,
                  bench::Better::Lower);
    // Scrolling on: the next page.
    const double f0 = bench::nowSeconds();
    view.searchBox()->setText("");
    view.applyFilter();
    view.model()->fetchMore({});
    app.processEvents();
    report.figure("history.next_page_ms", (bench::nowSeconds() - f0) * 1000, "ms", 50,
                  bench::Better::Lower);
    return report.exitCode();
}
