// Fuzz target: WorkspaceFile::fromJson, the lines a window, tipscope-cli --workspace and the
// agent open, from a file a person or a plant's tooling writes.
//
// The input is the file's content. Besides "no crash, no sanitizer report": a refusal says why
// and quotes no line's name whole (a 100 kB name comes back cut, as every echo does); an
// accepted workspace names each line once, keeps each line's work context within its bounds,
// and reads back the same from its own toJson().
#include "fuzzcheck.h"

#include "model/context/workcontextjson.h"
#include "model/workspace/workspacefile.h"

#include <QJsonDocument>
#include <QSet>

using namespace tipscope::model;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
    const QByteArray json(reinterpret_cast<const char *>(data), qsizetype(size));
    const auto file = WorkspaceFile::fromJson(QJsonDocument::fromJson(json).object());
    if (!file) {
        FUZZ_CHECK(!file.error().isEmpty());
        FUZZ_CHECK(file.error().size() < 1000);
        return 0;
    }
    QSet<QString> names;
    for (const WorkspaceLine &line : file->lines) {
        FUZZ_CHECK(!names.contains(line.name));
        names.insert(line.name);
        FUZZ_CHECK(workContextProblem(line.context).isEmpty());
    }
    const auto again = WorkspaceFile::fromJson(file->toJson());
    FUZZ_CHECK(again.ok());
    FUZZ_CHECK(again->lines.size() == file->lines.size());
    for (qsizetype i = 0; i < file->lines.size(); ++i)
        FUZZ_CHECK(again->lines.at(i).name == file->lines.at(i).name);
    return 0;
}
