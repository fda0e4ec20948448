// tipscope-cli profile save|diff|apply FILE: the technicians' profiles from a script.
#include "clicommands.h"

#include "model/profiles/profileapplier.h"

#include <QEventLoop>

namespace tipscope::cli {

using namespace tipscope::link;
using namespace tipscope::model;

namespace {

struct CliProfileTr {
    Q_DECLARE_TR_FUNCTIONS(CliProfile)
};

std::unique_ptr<DeviceModel> modelFor(CliSession &s) {
    const DeviceInfo *d = s.firstStation();
    if (!d && !s.devices().isEmpty())
        d = &s.devices().first();
    return d ? s.model(*d) : nullptr;
}

void waitIdle(CliSession &s) {
    QEventLoop loop;
    QTimer poll;
    QObject::connect(&poll, &QTimer::timeout, &loop, [&] {
        if (s.line().queue().pendingCount() == 0)
            loop.quit();
    });
    poll.start(10);
    loop.exec();
}

int save(CliSession &s, DeviceModel &device, const QString &path) {
    device.refreshAll(Priority::UserRead);
    waitIdle(s);
    QStringList missing;
    const Profile p = Profile::capture(device, &missing);
    if (!missing.isEmpty()) {
        s.err() << CliProfileTr::tr("tipscope-cli: could not read %1; no profile written")
                       .arg(missing.join(QLatin1Char(' ')))
                << Qt::endl;
        return s.line().state() == Line::State::Open ? kNoAnswer : kTransport;
    }
    if (const auto saved = p.save(path); !saved.ok()) {
        s.err() << "tipscope-cli: " << saved.error() << Qt::endl;
        return kUsage;
    }
    s.out() << CliProfileTr::tr("saved %1 settings of %2 to %3")
                   .arg(p.values.size())
                   .arg(device.displayName(), path)
            << Qt::endl;
    return kOk;
}

} // namespace

int runProfile(CliSession &s) {
    const QStringList &args = s.options().args;
    static const QStringList verbs = {QStringLiteral("save"), QStringLiteral("diff"),
                                      QStringLiteral("apply")};
    if (args.size() != 2 || !verbs.contains(args.at(0))) {
        s.err() << CliProfileTr::tr(
                       "tipscope-cli: profile takes save FILE, diff FILE or apply FILE")
                << Qt::endl;
        return kUsage;
    }
    const QString verb = args.at(0);
    const QString path = args.at(1);
    std::optional<Profile> profile;
    if (verb != QLatin1String("save")) {
        auto loaded = Profile::load(path);
        if (!loaded.ok()) {
            s.err() << "tipscope-cli: " << loaded.error() << Qt::endl;
            return kRefused;
        }
        profile = std::move(loaded).value();
    }
    if (const int rc = s.resolveDevices(); rc != kOk)
        return rc;
    auto device = modelFor(s);
    if (!device)
        return kNoAnswer;
    if (verb == QLatin1String("save"))
        return save(s, *device, path);
    const bool dryRun = s.options().flags.contains(QStringLiteral("dry-run"));
    const auto mode = verb == QLatin1String("diff") ? ProfileApplier::Mode::Diff
                      : dryRun                      ? ProfileApplier::Mode::DryRun
                                                    : ProfileApplier::Mode::Apply;
    ProfileApplier applier(*device, *profile, mode,
                           s.options().flags.contains(QStringLiteral("force")));
    QEventLoop loop;
    QObject::connect(&applier, &ProfileApplier::finished, &loop, &QEventLoop::quit);
    // Each write the dropped line fails only says "not connected"; why it dropped is said once.
    QString dropped;
    QObject::connect(&s.line(), &Line::stateChanged, &loop,
                     [&dropped](Line::State state, const QString &detail) {
                         if (state == Line::State::Retrying && dropped.isEmpty())
                             dropped = detail;
                     });
    applier.start();
    loop.exec();
    const ApplyReport &r = applier.report();
    if (r.refused) {
        s.err() << "tipscope-cli: " << r.text() << Qt::endl;
        return kRefused;
    }
    s.out() << r.text() << Qt::endl;
    if (!r.conflicts.isEmpty()) { // a diff: applying this profile would be refused
        s.err() << CliProfileTr::tr("tipscope-cli: applying this profile would be refused: %1")
                       .arg(r.conflictReason())
                << Qt::endl;
        return kRefused;
    }
    if (!dropped.isEmpty())
        s.err() << CliProfileTr::tr(
                       "tipscope-cli: the line was dropped during the apply: %1. A slow station "
                       "may need a longer --timeout (now %2 ms) or more --retries (now %3); "
                       "apply the profile again once the line answers: what is already right "
                       "is left alone")
                       .arg(dropped)
                       .arg(s.options().line.queue.turnaroundMs)
                       .arg(s.options().line.queue.retries)
                << Qt::endl;
    if (s.line().state() != Line::State::Open || !dropped.isEmpty())
        return kTransport;
    return r.failedCount() > 0 ? kNak : kOk;
}

} // namespace tipscope::cli
