// Reading a small JSON settings file (a workspace, the joint limits, the work context): opened,
// bounded in size, parsed to an object. Each caller words the failure for its own kind of file,
// so the reason comes back as what went wrong, not as a sentence.
#pragma once

#include <QJsonObject>
#include <QString>
#include <variant>

namespace tipscope::base::io {

struct JsonFileProblem {
    enum class Kind {
        Missing,    // the file does not exist
        Unreadable, // it exists but cannot be opened (detail: the system's reason)
        TooBig,     // larger than the limit
        NotAnObject // not JSON, or JSON but not an object (detail: the parser's reason, or
                    // empty for a document that is a list)
    };
    Kind kind;
    QString detail;
};

[[nodiscard]] std::variant<QJsonObject, JsonFileProblem> readJsonObject(const QString &path,
                                                                        qint64 maxBytes);

} // namespace tipscope::base::io
