#include "controller/link_texts.h"

#include "link/client.h"
#include "profile/problem.h"
#include "session/core_texts.h"
#include "session/diagnostic_texts.h"
#include "session/translated_texts.h"

#include <QCoreApplication>

#include <string>
#include <vector>

namespace k528::studio {

namespace {

// core/link/link_texts.cpp's catalog, each text marked for the translators.
const TranslatedText kLinks[] = {
        {"link.join", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "%1: %2")},
        {"link.then", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "%1; %2")},
        {"link.list", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "%1, %2")},
        {"link.exception-1", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "exception 01: the controller does not know this function")},
        {"link.exception-2", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "exception 02: a register outside the controller's map (or a read-only one written)")},
        {"link.exception-3", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "exception 03: a value outside its range; nothing of the request was written")},
        {"link.exception-6", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "exception 06: the controller is not in F7 «РАБОТА С ПЭВМ» (УПРАВЛЕНИЕ ДАННЫМИ): select it on the K923 to write")},
        {"link.exception", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "exception %1")},
        {"link.status-0", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "idle (the transfer)")},
        {"link.status-1", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "ready (the transfer)")},
        {"link.status-2", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "committed")},
        {"link.status-16", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "the controller is not in F7 «РАБОТА С ПЭВМ»")},
        {"link.status-17", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "no such program in the controller")},
        {"link.status-18", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "the controller refused the text")},
        {"link.status-19", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "CRC or length mismatch: the text arrived damaged and was not stored")},
        {"link.status-20", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "the controller's memory is full")},
        {"link.status", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "status %1")},
        {"link.reading", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "reading registers %1")},
        {"link.writing", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "writing registers %1")},
        {"link.echo", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "echo")},
        {"link.diagnostics", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "diagnostics %1")},
        {"link.server-id", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "server id")},
        {"link.no-answer", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "%1: the controller does not answer (%2 attempts)")},
        {"link.no-answer-1", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "%1: the controller does not answer (1 attempt)")},
        {"link.no-answer-last", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "%1: the controller does not answer (%2 attempts, last: %3)")},
        {"link.no-answer-1-last", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "%1: the controller does not answer (1 attempt, last: %2)")},
        {"link.timeout", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "timeout")},
        {"link.crc-error", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "CRC error")},
        {"link.port-closed", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "the port is closed")},
        {"link.connection-closed", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "the connection is closed")},
        {"link.echo-differs", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "the echo differs")},
        {"link.empty-answer", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "an empty answer")},
        {"link.port-reopen", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "the port is closed and does not open again: %1")},
        {"link.port-failed", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "the port failed: %1")},
        {"link.connection-reopen", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "the connection is closed and does not open again: %1")},
        {"link.connection-failed", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "the connection failed: %1")},
        {"link.cannot-connect", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "cannot connect to %1: %2")},
        {"link.damaged", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "%1 (a damaged frame)")},
        {"link.bad-reply", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "%1 (an answer that does not fit)")},
        {"link.lost", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "%1 (no answer)")},
        {"line.refused", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "connection refused")},
        {"line.remote-closed", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "the other end closed the connection")},
        {"line.host-not-found", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "host not found")},
        {"line.connect-timeout", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "no connection within %1 ms")},
        {"line.socket-timeout", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "the socket timed out")},
        {"line.network", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "the network is unreachable")},
        {"line.socket-access", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "access to the socket denied")},
        {"line.address-in-use", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "the address is in use")},
        {"line.socket-other", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "socket error: %1")},
        {"line.port-not-found", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "no such port")},
        {"line.port-permission", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "permission denied (or another program holds the port)")},
        {"line.port-open", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "the port is already open")},
        {"line.port-unsupported", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "the port does not take these settings")},
        {"line.port-gone", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "the port is gone (unplugged?)")},
        {"line.port-io", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "the port failed to read or write")},
        {"line.port-timeout", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "the port timed out")},
        {"line.port-not-open", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "the port is not open")},
        {"line.port-other", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "port error: %1")},
        {"line.bad-address", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "'%1' is not HOST:PORT (a port 1..65535)")},
        {"link.not-ready-menu", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "the controller is in F7 УПРАВЛЕНИЕ ДАННЫМИ but not on «РАБОТА С ПЭВМ»: choose «РАБОТА С ПЭВМ» in its menu on the K923 (▲ ▼, ENTER), then %1 again; nothing was sent")},
        {"link.not-ready-mode", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "the controller is not in F7 «РАБОТА С ПЭВМ» (mode F%2 now): press F7 (УПРАВЛЕНИЕ ДАННЫМИ) on the K923 and choose «РАБОТА С ПЭВМ», then %1 again; nothing was sent")},
        {"link.not-ready-power", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "the controller is not in F7 «РАБОТА С ПЭВМ» (powering on): press F7 (УПРАВЛЕНИЕ ДАННЫМИ) on the K923 and choose «РАБОТА С ПЭВМ», then %1 again; nothing was sent")},
        {"link.action-push", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "push (the action to repeat)")},
        {"link.action-clear-c", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "clear C (the action to repeat)")},
        {"link.action-clear-r", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "clear R (the action to repeat)")},
        {"link.action-set", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "set %1 (the action to repeat)")},
        {"link.part-c", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "C-parameters")},
        {"link.part-r", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "R-parameters")},
        {"link.part-r-range", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "R-parameters (%1)")},
        {"link.part-messages", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "messages")},
        {"link.part-program", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "program %1")},
        {"link.clear-c", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "clear C")},
        {"link.clear-r", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "clear R")},
        {"link.clear-c-not-zero", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "clear C: the C block does not read back as zeros")},
        {"link.text-length", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "the controller announces a text of %1 bytes")},
        {"link.text-crc", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "the text read does not match its CRC-32")},
        {"link.refused-at-line", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "%1 at line %2")},
        {"link.window-offset", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "the map's window does not follow its offset")},
        {"link.text-differs", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "%1: the text read back differs from the text sent")},
        {"link.block-refused", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "%1: the controller refused the block")},
        {"link.block-refused-at", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "%1: the controller refused the block at C%2")},
        {"link.block-differs", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "%1: the values read back differ from those sent")},
        {"link.c-no-address", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "C%1 has no address in the positioner (table Е.1): it cannot be written")},
        {"link.c-value-refused", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "C%1 = %2: the controller refused the value (outside table Е.1)")},
        {"link.read-back-differs", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "%1: the controller does not read back what was written")},
        {"link.r-read-only", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "R%1 is read only over the link (the PC writes %2)")},
        {"link.r-32-bits", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "R%1 = %2 is outside 32 bits")},
        {"link.nothing-sent", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "%1; nothing was sent")},
        {"link.c-table", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "C%1 (%2): %3 (table Е.1)")},
        {"link.r-outside", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "R%1 is outside the 32-bit range")},
        {"link.program-line", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "program %1, line %2: %3")},
        {"link.program-not-one", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "program %1 does not hold exactly that program")},
        {"link.program-says", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "program %1: %2")},
        {"link.file-line", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "%1:%2: %3")},
        {"link.file-empty", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "%1 holds no program (%L) and no %MESSAGES")},
        {"link.file-before-header", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "%1: the text before the first %L header belongs to no program")},
        {"link.file-controller", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "%1:%2: %3 (checked against the controller's constants and programs)")},
        {"link.push-new", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "new: %1")},
        {"link.push-in-doubt", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "in doubt (the line broke while it was committed; pull to see): %1")},
        {"link.push-as-it-was", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "as they were: %1")},
        {"link.stats-answer", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "%1 answer")},
        {"link.stats-answers", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "%1 answers")},
        {"link.stats-timeout", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "%1 timeout")},
        {"link.stats-timeouts", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "%1 timeouts")},
        {"link.stats-crc-error", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "%1 CRC error")},
        {"link.stats-crc-errors", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "%1 CRC errors")},
        {"link.stats-bad-reply", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "%1 bad reply")},
        {"link.stats-bad-replies", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "%1 bad replies")},
        {"link.stats-exception", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "%1 exception")},
        {"link.stats-exceptions", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "%1 exceptions")},
        {"link.stats-retry", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "%1 retry")},
        {"link.stats-retries", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "%1 retries")},
        {"link.stats-split", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "%1 request sent again in halves")},
        {"link.stats-splits", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "%1 requests sent again in halves")},
        {"link.stats-round-trip", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "; round trip median %1 ms, p95 %2 ms")},
        {"link.scan-station", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "address %1: %2")},
        {"link.scan-no-answer", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "no answer")},
        {"link.scan-garbled", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "a damaged answer (another baud rate or parity?)")},
        {"link.scan-echo-ok", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "echo ok")},
        {"link.scan-echo-exception", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "exception %1 to the echo")},
        {"link.scan-server-id", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "; server id %1")},
        {"link.scan-running", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", ", running (the server id says)")},
        {"link.scan-no-server-id", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "; no server id (FC 17)")},
        {"link.scan-map", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "; K528-05 map: mode F%1")},
        {"link.scan-program", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", ", program %1")},
        {"link.scan-programs", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", ", %1 programs")},
        {"link.scan-alarms", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", ", alarms")},
        {"link.scan-round-trip", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "; round trip %1 ms")},
        {"link.cancelled", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "cancelled by the user")},
        {"link.closed", QT_TRANSLATE_NOOP("k528::studio::LinkTexts", "closed")},
};

const TranslatedTexts kLinkTexts("k528::studio::LinkTexts", kLinks);

QString fromStd(const std::string& s) { return QString::fromUtf8(s.data(), static_cast<qsizetype>(s.size())); }

} // namespace

bool hasLinkText(std::string_view id) { return kLinkTexts.has(id); }

QString linkText(const link::Said& s) {
    if (s.diagnostic)
        return diagnosticText(*s.diagnostic);
    if (s.problem)
        return problemText(*s.problem);
    if (s.id.empty())
        return fromStd(s.word);
    if (!kLinkTexts.has(s.id))
        return fromStd(link::render(s, false)); // an id without a translation: core's words
    std::vector<std::string> args;
    args.reserve(s.args.size());
    for (const link::Said& a : s.args)
        args.push_back(linkText(a).toStdString());
    return *kLinkTexts.text(s.id, args);
}

QString linkErrorText(const link::LinkError& e) { return linkText(e.said); }

QString lineErrorText(const QString& error) { return linkText(link::decodeSaid(error.toStdString())); }

} // namespace k528::studio
