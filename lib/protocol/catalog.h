// Catalog: the one data-driven description of every command of every device family.
//
// It is loaded from two JSON resources (resources/catalog/families.json and commands.json) so
// that supporting a command or a family is a data change. A CommandSpec is one catalog entry with
// its pattern ("STx": port x; "Axy": port x, tool y); resolve() turns a concrete wire code ("ST1",
// "A12") for one family and direction into a ResolvedCommand with the family's numbers filled in
// (port and tool checked, temperature limits, enum table). The catalog is immutable after loading
// and safe to share; builtin() parses the embedded resources once, load() parses any other pair
// (tests load a catalog with extra entries). Each entry's role and group (catalogroles.h) say
// what it is for and where it is shown, so no model or page needs to spell its code.
#pragma once

#include "base/outcome.h"
#include "catalogroles.h"
#include "catalogtext.h"

#include <QByteArray>
#include <QList>
#include <QMap>
#include <QString>
#include <QStringList>
#include <optional>

namespace tipscope::protocol {

enum class Direction { Read, Write };
enum class ValueKind { Number, Delay, Hex, Text, Enum, Flags, Action };

struct Unit {
    QString key;      // "degC", "permille", ...
    QString symbol;   // wire unit as written in the guides
    QString display;  // unit shown to people (before the °C/°F choice)
    double scale = 1; // display = wire * scale
    int decimals = 0;
};

struct DigitField {
    int digit = 0; // 0 = units, 1 = tens, ...
    QString name;
    QMap<int, QString> values;
};

struct CommandSpec {
    QString pattern; // "STx", "Axy", "MAT"
    QString name;
    QString description;
    QString danger; // what happens, for confirmations of dangerous commands
    bool readable = false;
    bool writable = false;
    QStringList families;
    ValueKind kind = ValueKind::Number;
    QString unit = QStringLiteral("none");
    QString minToken, maxToken; // a number or "$tempMin" / "$tempMax"
    QString defaultToken;       // factory value: a number or "$factoryMat" etc.; may be empty
    int step = 1;
    QMap<int, QString> special;     // e.g. 99999 -> "disabled"
    QString table;                  // enum table name, may be "$toolTable" etc.
    QMap<int, QString> values;      // inline enum values
    QMap<int, QString> writeValues; // values a write may carry (flags kinds)
    QString digitsTable;
    QByteArray fixedData; // actions
    Group group = Group::Station;
    Role role = Role::None;
    // Counters: what is counted, shared by a total and its partial counter ("Plugged hours"),
    // so a table can put the two in one row; empty when the name says it.
    QString quantity;
    bool partial = false; // a partial counter, or its reset, beside a total one
    QString label;        // the words on a button that runs the command; empty: the name
    QString poll;
    bool dangerous = false;
    bool isVolatile = false;
    QString savedBy;
    QStringList clearsOnRead;
    QString limitMin, limitMax; // codes of other parameters bounding this one (MIT, MAT)

    [[nodiscard]] bool usesPort() const { return pattern.contains(QLatin1Char('x')); }
    [[nodiscard]] bool usesTool() const { return pattern.contains(QLatin1Char('y')); }
    [[nodiscard]] bool accepts(Direction d) const {
        return d == Direction::Read ? readable : writable;
    }
    // Actions are the write-only commands and those that carry fixed data (DeviceModel).
    [[nodiscard]] bool isAction() const { return kind == ValueKind::Action || !readable; }
};

struct FamilyInfo {
    QString name; // "DME"
    QString kind; // "station" or "feeder"
    QString title;
    QString guide;
    int ports = 0;
    QList<int> tools;
    QString toolTable;
    int tempMin = 0, tempMax = 0, factoryMat = 0, factoryMit = 0;
    int maxPowerW = 0; // 0 when the guide gives none
    bool addressedByDefault = true;
    int defaultAddress = 1;
    bool writeAnswerEchoesData = false;
    QString stationErrors, portErrors;
    int nakUndefined = 9;

    [[nodiscard]] bool isFeeder() const { return kind == QLatin1String("feeder"); }
};

struct ResolvedCommand {
    const CommandSpec *spec = nullptr;
    QString family;
    QByteArray code; // the 3-character wire command, e.g. "ST1"
    Direction direction = Direction::Read;
    int port = 0;  // 0 when the command has no port
    int tool = -1; // -1 when the command has no tool
    int min = 0, max = 0;
    std::optional<int> factoryDefault;
    QMap<int, QString> values; // resolved enum / write values

    [[nodiscard]] bool hasRange() const { return min != 0 || max != 0; }
};

class Catalog {
public:
    // Parses the two JSON documents; on error says why.
    [[nodiscard]] static base::Outcome<Catalog> load(const QByteArray &familiesJson,
                                                     const QByteArray &commandsJson);
    // The catalog embedded in the library. Aborts if the embedded data is broken, which a unit
    // test rules out.
    [[nodiscard]] static const Catalog &builtin();

    [[nodiscard]] QStringList familyNames() const { return m_familyOrder; }
    [[nodiscard]] const FamilyInfo *family(const QString &name) const;
    [[nodiscard]] const QList<CommandSpec> &commands() const { return m_commands; }
    [[nodiscard]] QMap<int, QString> table(const QString &name, const QString &family = {}) const;
    [[nodiscard]] const Unit *unit(const QString &key) const;
    [[nodiscard]] QList<DigitField> digits(const QString &tableName) const;
    [[nodiscard]] int address(const QString &role) const { return m_addresses.value(role, -1); }

    [[nodiscard]] std::optional<ResolvedCommand>
    resolve(const QString &family, const QByteArray &code, Direction direction) const;
    // Every concrete command of a family in one direction, ports and tools expanded.
    [[nodiscard]] QList<ResolvedCommand> expand(const QString &family, Direction direction) const;
    // Family whose name starts the model name reported by R-SMN ("DME-2C" -> "DME").
    [[nodiscard]] QString familyForModel(const QString &modelName) const;
    // The first entry with this role (among the family's, when one is named), for the few places
    // that must name a command before they know a device: identifying one, saying what a family
    // lacks. Null when there is none.
    [[nodiscard]] const CommandSpec *command(Role role, const QString &family = {}) const;
    // The concrete command of a role on a port (0: the device's own) of a family, in one
    // direction; none when the family lacks the role or it has no such port.
    [[nodiscard]] std::optional<ResolvedCommand> resolve(const QString &family, Role role, int port,
                                                         Direction direction) const;

    // What a code means, for people: the table's text, or a sentence for a code not listed.
    // Wording::Translated for what is shown, Wording::Catalog for data output (catalogtext.h).
    [[nodiscard]] QString nakText(int code, Wording wording) const;
    [[nodiscard]] QString stationErrorText(const QString &family, int code, Wording wording) const;
    [[nodiscard]] QString portErrorText(const QString &family, int code, Wording wording) const;
    [[nodiscard]] QString feederErrorText(int code, Wording wording) const;
    [[nodiscard]] QString severity(const QString &tableName, int code) const;
    // What support staff should check, in order, for an error code read with `command` (whose
    // table is an error table: $stationErrors, $portErrors, feederErrors), from the guides'
    // meanings; the table's advice for codes it does not list; empty for 0 (no error) or a
    // table without advice.
    [[nodiscard]] QString errorAdvice(const ResolvedCommand &command, int code,
                                      Wording wording) const;
    // Maps a misprinted code (the guides' 80000) to its table entry.
    [[nodiscard]] int canonicalPortError(int code) const;

private:
    QMap<QString, FamilyInfo> m_families;
    QStringList m_familyOrder;
    QList<CommandSpec> m_commands;
    QMap<QString, QMap<int, QString>> m_tables;
    QMap<QString, QList<DigitField>> m_digits;
    QMap<QString, QMap<int, QString>> m_severity;
    QMap<QString, QMap<int, QString>> m_advice; // code -1: any code the table does not list
    QMap<int, int> m_portErrorAliases;
    QMap<QString, Unit> m_units;
    QMap<QString, int> m_addresses;

    std::optional<ResolvedCommand> resolveSpec(const CommandSpec &spec, const FamilyInfo &family,
                                               const QByteArray &code, Direction direction) const;
    int resolveToken(const QString &token, const FamilyInfo &family) const;
    friend class CatalogLoader;
};

} // namespace tipscope::protocol
