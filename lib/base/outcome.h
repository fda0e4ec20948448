// Outcome: the one way a TipScope function reports a result that can fail.
//
// A function that can fail returns Outcome<T>: either the value, or the reason it failed, in
// words for the person who asked (translated where the text is user-visible). The reason is never
// empty. Outcome<void> is for actions that yield nothing but may fail (a save). The type is
// [[nodiscard]]: a failure cannot be dropped by accident. A layer that needs more than words (the
// CLI maps a failed identification to an exit code) gives its own error type as E.
//
//     Outcome<Profile> load(const QString &path) {
//         if (!f.open(QIODevice::ReadOnly))
//             return failure(Tr::tr("cannot read %1: %2").arg(path, f.errorString()));
//         return profile;
//     }
//     if (const auto p = Profile::load(path); p.ok()) use(p.value()); else show(p.error());
//
// value() on a failure is a programming error (asserted in debug); error() on a success is empty.
#pragma once

#include <QString>
#include <QtGlobal>
#include <utility>
#include <variant>

namespace tipscope::base {

// The failing half of an Outcome, so `return failure(why);` converts to any Outcome<T, E>.
template <typename E> struct Failure { E error; };

template <typename E> [[nodiscard]] Failure<E> failure(E error) {
    return {std::move(error)};
}

[[nodiscard]] inline Failure<QString> failure(const QString &error) {
    Q_ASSERT(!error.isEmpty());
    return {error};
}

template <typename T, typename E = QString> class [[nodiscard]] Outcome {
public:
    Outcome(T value) // NOLINT: implicit, so `return value;` reads naturally
        : m_state(std::in_place_index<0>, std::move(value)) {}
    Outcome(Failure<E> f) // NOLINT: implicit, so `return failure(why);` reads naturally
        : m_state(std::in_place_index<1>, std::move(f.error)) {}

    [[nodiscard]] bool ok() const { return m_state.index() == 0; }
    explicit operator bool() const { return ok(); }

    [[nodiscard]] const T &value() const & {
        Q_ASSERT(ok());
        return std::get<0>(m_state);
    }
    [[nodiscard]] T &&value() && {
        Q_ASSERT(ok());
        return std::get<0>(std::move(m_state));
    }
    const T *operator->() const { return &value(); }
    const T &operator*() const & { return value(); }

    // Empty (a default E) on success, so a test may print it whatever happened.
    [[nodiscard]] E error() const { return ok() ? E{} : std::get<1>(m_state); }

private:
    std::variant<T, E> m_state;
};

template <typename E> class [[nodiscard]] Outcome<void, E> {
public:
    Outcome() = default;  // success
    Outcome(Failure<E> f) // NOLINT: implicit, so `return failure(why);` reads naturally
        : m_error(std::move(f.error))
        , m_ok(false) {}

    [[nodiscard]] bool ok() const { return m_ok; }
    explicit operator bool() const { return ok(); }
    [[nodiscard]] const E &error() const { return m_error; } // empty on success

private:
    E m_error{};
    bool m_ok = true;
};

} // namespace tipscope::base
