#include "soakreport.h"

#include "benchsupport.h"

namespace tipscope::bench {

namespace {

void figure(const char *name, double value, const char *unit, int decimals = 0) {
    printFigure(QStringLiteral("soak.") + QLatin1String(name), value, QLatin1String(unit),
                decimals);
}

void printTraffic(const SoakResult &r) {
    figure("duration", r.seconds, "s", 1);
    figure("transactions", double(r.link.answered), "tx");
    figure("transactions_per_s", r.seconds > 0 ? double(r.link.answered) / r.seconds : 0, "tx/s",
           1);
    figure("frames_sent", double(r.link.sent), "frames");
    figure("polls", double(r.polls), "polls");
    figure("sim_requests", double(r.sim.requests), "requests");
    figure("sim_write_requests", double(r.sim.writes), "requests");
}

void printFaults(const SoakResult &r) {
    figure("injected.dropped", double(r.sim.dropped), "answers");
    figure("injected.corrupted", double(r.sim.corrupted), "answers");
    figure("injected.garbage", double(r.sim.garbled), "answers");
    figure("injected.requests_lost", double(r.sim.lostRequests), "requests");
    figure("injected.requests_garbled", double(r.sim.garbledRequests), "requests");
    figure("injected.nak", double(r.nakInjected), "requests");
    figure("injected.nak_windows", r.nakWindows, "windows");
    figure("injected.delayed", double(r.delayInjected), "requests");
    figure("injected.delay_windows", r.delayWindows, "windows");
    figure("injected.unplugs", double(r.unplugs.size()), "unplugs");
    figure("detected.timeouts", double(r.link.timeouts), "attempts");
    figure("detected.corrupted", double(r.link.corrupted), "frames");
    figure("detected.naks", double(r.link.nakTotal()), "answers");
    for (auto it = r.link.naks.cbegin(); it != r.link.naks.cend(); ++it)
        printFigure(QStringLiteral("soak.detected.nak_%1").arg(it.key(), 5, 10, QLatin1Char('0')),
                    double(it.value()), QStringLiteral("answers"), 0);
    figure("detected.stray", double(r.link.stray), "frames");
    figure("detected.late_answers", double(r.link.lateAnswers), "frames");
    figure("detected.discarded_bytes", double(r.link.discardedBytes), "bytes");
    figure("detected.retries", double(r.link.retries), "retries");
    figure("detected.line_reconnects", r.lineReconnects, "reconnects");
}

void printWrites(const SoakResult &r) {
    const WriteTally &w = r.writes;
    figure("writes.issued", double(w.issued), "writes");
    figure("writes.verified", double(w.verified), "writes");
    figure("writes.failed", double(w.failed), "writes");
    for (auto it = w.failedBy.cbegin(); it != w.failedBy.cend(); ++it)
        printFigure(QStringLiteral("soak.writes.failed_") + it.key(), double(it.value()),
                    QStringLiteral("writes"), 0);
    figure("writes.lost", r.lost, "writes");
    figure("writes.reported_twice", double(w.reportedTwice), "writes");
    figure("writes.unsolicited", double(w.unsolicited), "writes");
    figure("writes.refused_before_sending", double(w.refused), "writes");
    figure("writes.not_started", double(w.notStarted), "writes");
    figure("writes.verified_p50", quantile(w.verifiedMs, 0.5), "ms");
    figure("writes.verified_p99", quantile(w.verifiedMs, 0.99), "ms");
    figure("device.checks_after_writes", double(w.deviceChecks), "checks");
    figure("device.mismatch_after_writes", double(w.deviceMismatches), "checks");
    figure("device.codes_checked", r.codes - r.unreadable, "codes");
    figure("device.unreadable", r.unreadable, "codes");
    figure("device.unexpected_values", r.unexpected, "codes");
    figure("device.value_from_failed_write", r.fromFailedWrite, "codes");
    figure("pending_after_drain", r.pendingAfterDrain, "requests");
    figure("pending_at_end", r.pendingAtEnd, "requests");
    for (const QString &e : w.examples)
        printNote(QStringLiteral("failed write: ") + e);
    for (const QString &m : w.mismatches)
        printNote(QStringLiteral("device mismatch: ") + m);
}

void printResources(const SoakResult &r) {
    figure("rss_start", double(r.rssStartKiB), "KiB");
    figure("rss_end", double(r.rssEndKiB), "KiB");
    figure("rss_peak", double(r.rssPeakKiB), "KiB");
    figure("sim_rss_start", double(r.simRssStartKiB), "KiB");
    figure("sim_rss_end", double(r.simRssEndKiB), "KiB");
    int recovered = 0;
    qint64 worst = 0;
    for (int i = 0; i < r.unplugs.size(); ++i) {
        const SoakUnplug &u = r.unplugs.at(i);
        printFigure(QStringLiteral("soak.unplug_%1.detect").arg(i + 1), double(u.detectMs),
                    QStringLiteral("ms"), 0);
        printFigure(QStringLiteral("soak.unplug_%1.recovery").arg(i + 1), double(u.recoveryMs),
                    QStringLiteral("ms"), 0);
        if (u.recoveryMs >= 0)
            ++recovered;
        worst = qMax(worst, u.recoveryMs);
    }
    figure("recoveries", recovered, "recoveries");
    figure("recovery_max", double(worst), "ms");
}

} // namespace

bool printSoakReport(const SoakResult &r) {
    printTraffic(r);
    printFaults(r);
    printWrites(r);
    printResources(r);
    int recovered = 0;
    for (const SoakUnplug &u : r.unplugs)
        recovered += u.recoveryMs >= 0;
    const WriteTally &w = r.writes;
    const bool ledgerOk = r.lost == 0 && w.unsolicited == 0 && w.reportedTwice == 0 &&
                          w.refused == 0 && w.notStarted == 0 && w.deviceMismatches == 0;
    const bool pass = ledgerOk && r.unexpected == 0 && r.unreadable == 0 && r.pendingAtEnd == 0 &&
                      r.pendingAfterDrain == 0 && recovered == r.unplugs.size() && w.verified > 0;
    printText(QStringLiteral("soak.result"),
              pass ? QStringLiteral("pass") : QStringLiteral("FAIL"));
    return pass;
}

} // namespace tipscope::bench
