#include "profileapplier.h"

#include "model/device/devicemodel.h"
#include "profilelimits.h"

#include "protocol/hexbytes.h"

#include <QCoreApplication>
#include <QCryptographicHash>
#include <QJsonArray>
#include <QJsonObject>
#include <QTimer>

namespace tipscope::model {

using namespace tipscope::link;
using namespace tipscope::protocol;

namespace {
struct ProfileApplierTr {
    Q_DECLARE_TR_FUNCTIONS(ProfileApplier)
};
} // namespace

int ApplyReport::failedCount() const {
    return int(
        std::count_if(written.begin(), written.end(), [](const ApplyItem &i) { return !i.ok; }));
}

QString ApplyReport::text() const {
    QStringList lines;
    if (refused)
        lines.append(ProfileApplierTr::tr("refused, nothing was written: %1").arg(reason));
    for (const ProfileDifference &d : differences)
        if (!refused && (diffOnly || dryRun))
            lines.append(
                ProfileApplierTr::tr("%1 %2: %3 → %4")
                    .arg(QString::fromLatin1(d.code), d.name, d.deviceText, d.profileText));
    for (const ApplyItem &i : written)
        lines.append(i.ok ? ProfileApplierTr::tr("changed %1 %2: %3 → %4")
                                .arg(QString::fromLatin1(i.code), i.name, i.before, i.after)
                          : ProfileApplierTr::tr("FAILED %1 %2: %3")
                                .arg(QString::fromLatin1(i.code), i.name, i.reason));
    for (const QString &f : frames)
        lines.append(ProfileApplierTr::tr("would send %1").arg(f));
    for (const SkippedSetting &s : skipped)
        lines.append(ProfileApplierTr::tr("skipped %1 %2: %3")
                         .arg(QString::fromLatin1(s.code), s.name, s.reason));
    if (cancelled)
        lines.append(ProfileApplierTr::tr("cancelled: the remaining values were not written"));
    const QString skips = skipped.isEmpty()
                              ? QString()
                              : ProfileApplierTr::tr("%n skipped", nullptr, int(skipped.size()));
    if (refused) {
        if (!skips.isEmpty())
            lines.append(skips);
        return lines.join(QLatin1Char('\n'));
    }
    // A dry run writes nothing: counting what it wrote said "0 changed" for every profile.
    QString total = diffOnly
                        ? ProfileApplierTr::tr("%n difference(s)", nullptr, int(differences.size()))
                    : dryRun ? ProfileApplierTr::tr("%1 would change, %2 already right")
                                   .arg(frames.size())
                                   .arg(unchanged)
                             : ProfileApplierTr::tr("%1 changed, %2 already right, %3 failed")
                                   .arg(written.size() - failedCount())
                                   .arg(unchanged)
                                   .arg(failedCount());
    if (!skips.isEmpty())
        total += QStringLiteral(", ") + skips;
    lines.append(total);
    return lines.join(QLatin1Char('\n'));
}

QStringList ApplyReport::skippedCodes() const {
    QStringList codes;
    for (const SkippedSetting &s : skipped)
        codes.append(QString::fromLatin1(s.code));
    return codes;
}

QString ApplyReport::conflictReason() const {
    if (conflicts.isEmpty())
        return {};
    return ProfileApplierTr::tr(
               "the profile would break the limits that bound its settings (MIT ≤ MAT, "
               "MIT ≤ selected temperature ≤ MAT):\n%1")
        .arg(conflicts.join(QLatin1Char('\n')));
}

ProfileApplier::ProfileApplier(DeviceModel &device, const Profile &profile, Mode mode, bool force,
                               QObject *parent)
    : QObject(parent)
    , m_device(device)
    , m_profile(profile)
    , m_mode(mode)
    , m_force(force) {
    m_report.dryRun = mode == Mode::DryRun;
    m_report.diffOnly = mode == Mode::Diff;
}

void ProfileApplier::start() {
    if (m_profile.family != m_device.family()) {
        keepSharedSettings();
        if (m_profile.values.isEmpty()) {
            refuse(ProfileApplierTr::tr(
                       "none of the profile's settings exists on this %1 (skipped: %2)")
                       .arg(m_device.family(), m_report.skippedCodes().join(QLatin1Char(' '))));
            return;
        }
        if (!m_force)
            m_refuseAfterCompare =
                ProfileApplierTr::tr("the profile is for a %1, this device is a %2 (force "
                                     "to apply the settings they share)")
                    .arg(m_profile.family, m_device.family());
    }
    if (m_mode == Mode::Apply && m_device.writesBlocked()) {
        refuse(ProfileApplierTr::tr("monitor-only mode is on"));
        return;
    }
    readAll();
}

void ProfileApplier::keepSharedSettings() {
    Profile kept = m_profile;
    kept.values.clear();
    for (const auto &entry : std::as_const(m_profile.values)) {
        const Parameter *p = m_device.parameter(entry.first);
        const QStringList problems =
            p && Profile::isProfileParameter(*p)
                ? Profile{m_device.family(), {}, {}, {}, {}, {entry}, {}}.problemsFor(
                      m_device.family())
                : QStringList{
                      ProfileApplierTr::tr("this %1 has no such setting").arg(m_device.family())};
        if (problems.isEmpty()) {
            kept.values.append(entry);
            continue;
        }
        // problemsFor() says "CODE: why"; the code has its own column.
        QString why = problems.join(QLatin1String("; "));
        const QString prefix = QString::fromLatin1(entry.first) + QStringLiteral(": ");
        if (why.startsWith(prefix))
            why = why.mid(prefix.size());
        m_report.skipped.append({entry.first, skippedName(entry.first), why});
    }
    m_profile = kept;
}

QString ProfileApplier::skippedName(const QByteArray &code) const {
    if (const Parameter *p = m_device.parameter(code))
        return m_device.qualifiedLabel(*p);
    const Catalog &cat = m_device.catalog();
    if (const auto w = cat.resolve(m_profile.family, code, Direction::Write))
        return qualifiedName(cat, *w);
    const auto note = m_profile.notes.find(code);
    return note != m_profile.notes.end() ? note->name : QString::fromLatin1(code);
}

void ProfileApplier::refuse(const QString &reason) {
    m_report.refused = true;
    m_report.reason = reason;
    QTimer::singleShot(0, this, &ProfileApplier::finish);
}

void ProfileApplier::readAll() {
    // The profile's settings, and the device's settings that bound them or that they bound.
    const QList<QByteArray> codes = limitRelatedCodes(m_profile, m_device);
    const int total = int(codes.size());
    m_pendingReads = 0;
    for (const QByteArray &code : codes) {
        Reply *r = m_device.parameter(code)->refresh(Priority::UserRead);
        if (!r)
            continue;
        ++m_pendingReads;
        connect(r, &Reply::finished, this, [this, total, r, code] {
            if (!r->ok())
                m_unread.insert(code);
            Q_EMIT progress(total - m_pendingReads + 1, total,
                            ProfileApplierTr::tr("reading the device"));
            if (--m_pendingReads == 0)
                compare();
        });
    }
    if (m_pendingReads == 0)
        QTimer::singleShot(0, this, &ProfileApplier::compare);
}

void ProfileApplier::compare() {
    m_report.differences = diffProfile(m_profile, m_device);
    m_report.unchanged = int(m_profile.values.size() - m_report.differences.size());
    m_report.conflicts = limitConflicts(m_profile, m_device, m_unread);
    if (!m_report.conflicts.isEmpty() && m_mode != Mode::Diff) {
        m_report.refused = true;
        m_report.reason = m_report.conflictReason();
    }
    if (!m_refuseAfterCompare.isEmpty()) {
        m_report.refused = true;
        m_report.reason = m_refuseAfterCompare;
    }
    if (m_report.refused || m_mode == Mode::Diff) {
        finish();
        return;
    }
    QList<QByteArray> codes;
    for (const ProfileDifference &d : std::as_const(m_report.differences))
        codes.append(d.code);
    m_toWrite = limitSafeOrder(codes, m_profile, m_device);
    if (m_mode == Mode::DryRun) {
        listFrames();
        finish();
        return;
    }
    m_next = 0;
    writeNext();
}

void ProfileApplier::listFrames() {
    for (const QByteArray &code : std::as_const(m_toWrite)) {
        Frame f = Frame::write(code, profileValue(code));
        if (m_device.address())
            f = f.addressed(m_device.queue().settings().robotAddress, *m_device.address());
        m_report.frames.append(QStringLiteral("%1  (%2)").arg(toHexText(f.encode()), f.toString()));
    }
}

void ProfileApplier::writeNext() {
    if (m_cancelled && m_next < m_toWrite.size()) {
        m_report.cancelled = true;
        finish();
        return;
    }
    if (m_next >= m_toWrite.size()) {
        finish();
        return;
    }
    const QByteArray code = m_toWrite.at(m_next++);
    Parameter *p = m_device.parameter(code);
    const QByteArray data = profileValue(code);
    const QString name = m_device.qualifiedLabel(*p);
    ApplyItem item{code, name, p->displayText(), {}, false, {}};
    Q_EMIT progress(m_next, int(m_toWrite.size()), ProfileApplierTr::tr("writing %1").arg(name));
    const auto value = decodeAnswer(p->spec(), data);
    const QString why =
        value ? p->setEdit(value->number) : ProfileApplierTr::tr("unreadable value");
    if (!why.isEmpty()) {
        item.reason = why;
        m_report.written.append(item);
        QTimer::singleShot(0, this, &ProfileApplier::writeNext);
        return;
    }
    if (p->state() == Parameter::State::InSync) { // already right (the device changed meanwhile)
        ++m_report.unchanged;
        QTimer::singleShot(0, this, &ProfileApplier::writeNext);
        return;
    }
    connect(
        p, &Parameter::writeFinished, this,
        [this, p, item](bool ok, const QString &reason) mutable {
            item.ok = ok;
            item.reason = reason;
            item.after = p->displayText();
            m_report.written.append(item);
            writeNext();
        },
        Qt::SingleShotConnection);
    p->apply();
}

QByteArray ProfileApplier::profileValue(const QByteArray &code) const {
    for (const auto &[c, data] : m_profile.values)
        if (c == code)
            return data;
    return {};
}

void ProfileApplier::finish() {
    if (m_mode == Mode::Apply && !m_report.refused)
        logApply();
    Q_EMIT finished(m_report);
}

// For audit: which profile (its hash), what it changed and what failed, as one event.
void ProfileApplier::logApply() {
    const QByteArray hash =
        QCryptographicHash::hash(m_profile.toJson(), QCryptographicHash::Sha256).toHex();
    QJsonArray changes;
    int failed = 0;
    for (const ApplyItem &item : std::as_const(m_report.written)) {
        changes.append(QJsonObject{{QStringLiteral("code"), QString::fromLatin1(item.code)},
                                   {QStringLiteral("name"), item.name},
                                   {QStringLiteral("before"), item.before},
                                   {QStringLiteral("after"), item.after},
                                   {QStringLiteral("ok"), item.ok},
                                   {QStringLiteral("reason"), item.reason}});
        failed += item.ok ? 0 : 1;
    }
    const QJsonObject details{{QStringLiteral("profileSha256"), QString::fromLatin1(hash)},
                              {QStringLiteral("comment"), m_profile.comment},
                              {QStringLiteral("changes"), changes},
                              {QStringLiteral("unchanged"), m_report.unchanged},
                              {QStringLiteral("cancelled"), m_report.cancelled}};
    const QString text =
        ProfileApplierTr::tr("profile %1 applied: %2 changed, %3 failed, %4 already right%5")
            .arg(QString::fromLatin1(hash.left(12)))
            .arg(m_report.written.size() - failed)
            .arg(failed)
            .arg(m_report.unchanged)
            .arg(m_report.cancelled ? ProfileApplierTr::tr(" (cancelled)") : QString());
    m_device.logEvent(Event::Kind::ProfileApply,
                      m_report.ok() ? Event::Severity::Info : Event::Severity::Warning, 0, text,
                      details);
}

} // namespace tipscope::model
