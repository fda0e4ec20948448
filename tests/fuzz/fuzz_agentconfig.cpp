// Fuzz target: AgentConfig::load, the file tipscope-agent reads at its start and again on every
// SIGHUP, written by a person or by a plant's deployment tooling.
//
// The input is the file's content, beside a workspace (lines.json) and a password file
// (password) it may name. Besides "no crash, no sanitizer report": a refusal says why in under
// 1,000 characters beyond the file's own path; an accepted configuration holds every value
// within the bounds docs/mqtt.md gives, and a password only from a file or variable it names; and
// the same bytes read twice give the same answer, as SIGHUP relies on.
#include "fuzzcheck.h"

#include "plant/agentconfig.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>

using namespace tipscope::plant;

namespace {

struct Folder {
    Folder() {
        write(QStringLiteral("lines.json"),
              R"({"format": "tipscope-workspace", "version": 1,
                  "lines": [{"name": "cell-1", "connection": {"kind": "demo"}}]})");
        write(QStringLiteral("password"), "s3cret\n");
    }
    void write(const QString &name, const QByteArray &bytes) const {
        QFile f(dir.filePath(name));
        if (!f.open(QIODevice::WriteOnly) || f.write(bytes) != bytes.size())
            std::abort();
    }
    QTemporaryDir dir;
};

bool sameOutcome(const tipscope::base::Outcome<AgentConfig> &a,
                 const tipscope::base::Outcome<AgentConfig> &b) {
    if (a.ok() != b.ok())
        return false;
    if (!a.ok())
        return a.error() == b.error();
    return a->site == b->site && a->broker.host == b->broker.host &&
           a->broker.port == b->broker.port && a->live.intervalMs == b->live.intervalMs &&
           a->workspace.toJson() == b->workspace.toJson();
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
    static const Folder folder;
    const QString path = folder.dir.filePath(QStringLiteral("agent.json"));
    folder.write(QStringLiteral("agent.json"),
                 QByteArray(reinterpret_cast<const char *>(data), qsizetype(size)));
    const auto config = AgentConfig::load(path);
    FUZZ_CHECK(sameOutcome(config, AgentConfig::load(path)));
    if (!config) {
        FUZZ_CHECK(!config.error().isEmpty());
        FUZZ_CHECK(config.error().size() < path.size() + 1000);
        return 0;
    }
    FUZZ_CHECK(!config->site.trimmed().isEmpty());
    FUZZ_CHECK(config->site.size() <= AgentConfig::kMaxSiteChars);
    FUZZ_CHECK(!config->broker.host.isEmpty());
    FUZZ_CHECK(config->broker.port >= 1 && config->broker.port <= 65535);
    FUZZ_CHECK(config->live.intervalMs >= 100 && config->live.intervalMs <= 3'600'000);
    FUZZ_CHECK(config->live.batchMs >= 0 && config->live.batchMs <= 600'000);
    FUZZ_CHECK(config->countersIntervalS >= 10 && config->countersIntervalS <= 86'400);
    // A password comes only from a file or a variable the configuration names.
    FUZZ_CHECK(config->broker.password.isEmpty() || !config->passwordSource.isEmpty());
    return 0;
}
