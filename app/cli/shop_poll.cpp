#include "shop_poll.h"

#include <QThread>
#include <chrono>

namespace k528::shop {

std::int64_t unixMsNow() {
    return std::chrono::duration_cast<std::chrono::milliseconds>(std::chrono::system_clock::now().time_since_epoch())
        .count();
}

linkplugin::LineSettings lineSettings(const profile::LineAddress& a, int timeoutMs) {
    linkplugin::LineSettings s;
    s.port = QString::fromStdString(profile::lineEndpoint(a));
    s.baud = a.baud;
    s.parity = a.parity;
    s.stopBits = a.stopBits;
    s.address = a.address;
    s.timeoutMs = timeoutMs;
    return s;
}

// A line's client: opened on its worker thread (its socket or port belongs
// there), opened again at the next poll when it could not be.
struct Poller::Worker {
    std::vector<std::size_t> indices; // the machines on this line
    linkplugin::LineSettings settings;
    linkplugin::LinkPlugin* plugin = nullptr;
    std::unique_ptr<linkplugin::ClientTransport> transport;
    std::unique_ptr<link::Link> link;
};

Poller::Poller(std::vector<LineRef> lines, int timeoutMs, QString& error)
    : lines_(std::move(lines)), timeoutMs_(timeoutMs) {
    linkplugin::LinkPlugin* tcp = nullptr;
    linkplugin::LinkPlugin* rtu = nullptr;
    for (std::size_t i = 0; i < lines_.size(); ++i) {
        const profile::LineAddress& a = lines_[i].address;
        const bool isTcp = a.kind == profile::LineAddress::Kind::Tcp;
        linkplugin::LinkPlugin*& p = isTcp ? tcp : rtu;
        if (!p && !(p = linkplugin::find(isTcp ? QStringLiteral("modbus-tcp") : QStringLiteral("modbus-rtu"), error))) {
            ok_ = false;
            return;
        }
        if (!isTcp) {
            bool shared = false;
            for (auto& w : workers_)
                if (w->plugin == p && w->settings.port == QString::fromStdString(a.device)) {
                    w->indices.push_back(i);
                    shared = true;
                    break;
                }
            if (shared)
                continue;
        }
        auto w = std::make_unique<Worker>();
        w->indices.push_back(i);
        w->settings = lineSettings(a, timeoutMs_);
        w->plugin = p;
        workers_.push_back(std::move(w));
    }
}

Poller::~Poller() { stop(); }

void Poller::pollWorker(Worker& w, const std::function<void(const PollResult&)>& sink) {
    if (!w.transport) {
        QString error;
        w.transport = w.plugin->openClient(w.settings, error);
        if (!w.transport) {
            for (std::size_t i : w.indices) {
                PollResult r;
                r.index = i;
                r.said = link::say("link.cannot-connect", {w.settings.port.toStdString(),
                                                           link::decodeSaid(error.toStdString())});
                r.why = link::render(r.said, false);
                r.atMs = unixMsNow();
                sink(r);
            }
            return;
        }
        // Two attempts: a dead line is told within two timeouts, not four.
        w.link = std::make_unique<link::Link>(*w.transport, link::k528Map(), 2);
    }
    for (std::size_t i : w.indices) {
        PollResult r;
        r.index = i;
        w.transport->setStation(lines_[i].address.address);
        if (link::LinkError e = link::readLive(*w.link, r.live)) {
            r.said = e.said;
            r.why = e.text(false);
        } else {
            r.online = true;
            r.roundTripMs = w.link->stats().roundTrip.last();
        }
        r.atMs = unixMsNow();
        sink(r);
    }
}

std::vector<PollResult> Poller::pollOnce() {
    std::vector<PollResult> out(lines_.size());
    std::mutex outM;
    const auto into = [&](const PollResult& r) {
        std::lock_guard lock(outM);
        out[r.index] = r;
    };
    std::vector<QThread*> threads;
    for (auto& wp : workers_) {
        Worker* w = wp.get();
        QThread* t = QThread::create([this, w, &into] {
            pollWorker(*w, into);
            w->link.reset();
            w->transport.reset(); // closed on the thread that opened it
        });
        t->start();
        threads.push_back(t);
    }
    for (QThread* t : threads) {
        t->wait();
        delete t;
    }
    return out;
}

void Poller::start(int intervalMs, std::function<void(const PollResult&)> sink) {
    stop();
    stopping_ = false;
    for (auto& wp : workers_) {
        Worker* w = wp.get();
        QThread* t = QThread::create([this, w, intervalMs, sink] {
            auto next = std::chrono::steady_clock::now();
            while (!stopping_) {
                pollWorker(*w, sink);
                next += std::chrono::milliseconds(intervalMs);
                const auto now = std::chrono::steady_clock::now();
                if (next < now)
                    next = now; // a poll longer than the interval: the next one at once, no burst after it
                std::unique_lock lock(m_);
                cv_.wait_until(lock, next, [this] { return stopping_.load(); });
            }
            w->link.reset();
            w->transport.reset();
        });
        t->start();
        threads_.push_back(t);
    }
}

void Poller::stop() {
    {
        std::lock_guard lock(m_);
        stopping_ = true;
    }
    cv_.notify_all();
    for (QThread* t : threads_) {
        t->wait();
        delete t;
    }
    threads_.clear();
}

} // namespace k528::shop
