// The catalog's words in the user interface language.
//
// The catalog (resources/catalog/*.json) is English and stays so: the wire, profiles, CSV files
// and what tipscope-cli prints as data use its words as they are, so that scripts can read them
// whatever the user's language. Only what people read passes through catalogText(), which looks
// the English text up under the translation context "Catalog"; scripts/gen-catalog-strings
// lists every such text in catalogstrings.cpp so that lupdate finds them.
#pragma once

#include <QString>

namespace tipscope::protocol {

// Whose words a text made from the catalog is in: the catalog's own English (data for scripts),
// or the user interface language (what people read).
enum class Wording { Catalog, Translated };

// `english`, a text of the catalog, in the user interface language; itself when the installed
// translators do not know it (English, or a text that is not the catalog's).
[[nodiscard]] QString catalogText(const QString &english);
// `english` in `wording`: itself for Wording::Catalog, catalogText(english) otherwise.
[[nodiscard]] QString catalogText(const QString &english, Wording wording);

} // namespace tipscope::protocol
