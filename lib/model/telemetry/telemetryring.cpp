// Storage side of TelemetryRing: construction, append and the incremental block summaries.
// The queries are in telemetryringquery.cpp.
#include "telemetryring.h"

#include <limits>

namespace tipscope::model {

namespace {

// Each summary level is 64 times coarser than the one below: few enough levels that append
// stays cheap, and at most 63 raw samples or blocks are read at each edge of a query range.
constexpr int kLevelShift = 6;
static_assert(1 << kLevelShift == TelemetryRing::kFinestBlock);
// The first allocation; storage then doubles up to the capacity.
constexpr size_t kFirstReserve = 1024;

// Grows `v` ahead of a push_back the way the sample columns grow: doubling, but never past
// `limit`, so that a full buffer holds exactly what it needs and memoryBytes() stays honest.
template <typename T> void reserveForOneMore(std::vector<T> &v, size_t limit, size_t first) {
    if (v.size() < v.capacity())
        return;
    v.reserve(qMin(limit, qMax(first, v.capacity() * 2)));
}

} // namespace

TelemetryRing::TelemetryRing(int seriesCount, int capacity)
    : m_capacity(qMax(1, capacity))
    , m_columns(size_t(qMax(0, seriesCount))) {
    // A level whose block is longer than the ring could never hold a whole block.
    for (int shift = kLevelShift; shift < 31 && (qint64(1) << shift) <= m_capacity;
         shift += kLevelShift) {
        const qint64 blockSize = qint64(1) << shift;
        Level level;
        level.shift = shift;
        // As many slots as blocks the ring spans: a block being started takes the slot of one
        // whose first sample has just left the ring, and such a block is never used whole.
        level.slots = (m_capacity + blockSize - 1) / blockSize;
        m_levels.push_back(std::move(level));
    }
}

void TelemetryRing::append(qint64 timeMs, const qint32 *values) {
    if (m_total - m_lapStart == m_capacity)
        m_lapStart = m_total;
    const qsizetype pos = position(m_total);
    if (m_total < m_capacity) {
        if (m_times.size() == m_times.capacity())
            growStorage();
        m_times.push_back(timeMs);
    } else {
        m_times[size_t(pos)] = timeMs;
    }
    for (size_t s = 0; s < m_columns.size(); ++s)
        m_columns[s].store(pos, values[s]);
    updateSummaries(m_total, values);
    ++m_total;
    m_lastTime = timeMs;
}

void TelemetryRing::dropOldest(qint64 count) {
    m_dropped = qMin(m_total, oldestIndex() + qMax<qint64>(0, count));
}

void TelemetryRing::growStorage() {
    const size_t limit = size_t(m_capacity);
    reserveForOneMore(m_times, limit, kFirstReserve);
    for (Values &column : m_columns)
        column.reserve(qsizetype(m_times.capacity()));
}

// Summaries are keyed by absolute sample number, so the ring overwriting a sample needs no
// repair here: a block that lost samples is simply never used whole by a query.
void TelemetryRing::updateSummaries(qint64 index, const qint32 *values) {
    const size_t series = m_columns.size();
    for (Level &level : m_levels) {
        const qint64 block = index >> level.shift;
        const auto offset = quint32(index - (block << level.shift));
        const size_t base = size_t(block % level.slots) * series;
        if (offset == 0) {
            const bool fresh = base == level.summaries.size();
            for (size_t s = 0; s < series; ++s) {
                const Summary start{values[s], values[s], values[s], 0, 0};
                if (fresh) {
                    reserveForOneMore(level.summaries, size_t(level.slots) * series, 16 * series);
                    level.summaries.push_back(start);
                } else {
                    level.summaries[base + s] = start;
                }
            }
            continue;
        }
        for (size_t s = 0; s < series; ++s) {
            Summary &summary = level.summaries[base + s];
            const qint32 value = values[s];
            // Strict comparisons keep the earliest extreme, as a raw scan would.
            if (value < summary.min) {
                summary.min = value;
                summary.minOffset = offset;
            }
            if (value > summary.max) {
                summary.max = value;
                summary.maxOffset = offset;
            }
            summary.sum += value;
        }
    }
}

qint64 TelemetryRing::memoryBytes() const {
    qint64 bytes = qint64(sizeof(*this));
    bytes += qint64(m_times.capacity() * sizeof(qint64));
    bytes += qint64(m_columns.capacity() * sizeof(Values));
    for (const Values &column : m_columns)
        bytes += column.bytes();
    bytes += qint64(m_levels.capacity() * sizeof(Level));
    for (const Level &level : m_levels)
        bytes += qint64(level.summaries.capacity() * sizeof(Summary));
    return bytes;
}

void TelemetryRing::Values::store(qsizetype pos, qint32 value) {
    const bool fitsNarrow =
        value >= std::numeric_limits<qint16>::min() && value <= std::numeric_limits<qint16>::max();
    if (!m_isWide && !fitsNarrow)
        widen();
    if (m_isWide) {
        if (size_t(pos) == m_wide.size())
            m_wide.push_back(value);
        else
            m_wide[size_t(pos)] = value;
    } else {
        if (size_t(pos) == m_narrow.size())
            m_narrow.push_back(qint16(value));
        else
            m_narrow[size_t(pos)] = qint16(value);
    }
}

void TelemetryRing::Values::reserve(qsizetype slots) {
    if (m_isWide)
        m_wide.reserve(size_t(slots));
    else
        m_narrow.reserve(size_t(slots));
}

qint64 TelemetryRing::Values::bytes() const {
    return qint64(m_narrow.capacity() * sizeof(qint16) + m_wide.capacity() * sizeof(qint32));
}

// Once per series at most: temperatures, per mille and status codes fit in 16 bits, but a
// value that does not must be kept exactly rather than clipped.
void TelemetryRing::Values::widen() {
    m_wide.reserve(m_narrow.capacity());
    m_wide.assign(m_narrow.begin(), m_narrow.end());
    std::vector<qint16>().swap(m_narrow);
    m_isWide = true;
}

} // namespace tipscope::model
