#include "base/atomicsave.h"

#include "base/elide.h"

#include <QCoreApplication>
#include <QSaveFile>

namespace tipscope::base::io {

namespace {
struct AtomicSaveTr {
    Q_DECLARE_TR_FUNCTIONS(AtomicSave)
};
} // namespace

base::Outcome<void> saveAtomically(const QString &path, const QByteArray &bytes) {
    return saveAtomically(path,
                          [&bytes](QIODevice &file) { return file.write(bytes) == bytes.size(); });
}

base::Outcome<void> saveAtomically(const QString &path,
                                   const std::function<bool(QIODevice &)> &write) {
    QSaveFile f(path);
    if (f.open(QIODevice::WriteOnly) && write(f) && f.commit())
        return {};
    return base::failure(
        AtomicSaveTr::tr("cannot write %1: %2").arg(base::elidedPath(path), f.errorString()));
}

} // namespace tipscope::base::io
