#include "model/io/atomicsave.h"

#include "protocol/elide.h"

#include <QCoreApplication>
#include <QSaveFile>

namespace tipscope::model::io {

namespace {
struct AtomicSaveTr {
    Q_DECLARE_TR_FUNCTIONS(AtomicSave)
};
} // namespace

protocol::Outcome<void> saveAtomically(const QString &path, const QByteArray &bytes) {
    return saveAtomically(path,
                          [&bytes](QIODevice &file) { return file.write(bytes) == bytes.size(); });
}

protocol::Outcome<void> saveAtomically(const QString &path,
                                       const std::function<bool(QIODevice &)> &write) {
    QSaveFile f(path);
    if (f.open(QIODevice::WriteOnly) && write(f) && f.commit())
        return {};
    return protocol::failure(
        AtomicSaveTr::tr("cannot write %1: %2").arg(protocol::elidedPath(path), f.errorString()));
}

} // namespace tipscope::model::io
