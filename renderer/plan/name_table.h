// The renderer's name tables are common/name_table.h's: the plan's passes, draws and predicates
// and the render choices (render_choices.h) are named with it.
#pragma once

#include "common/name_table.h"

namespace monoplane::modes {

using monoplane::find_name;
using monoplane::joined_names;
using monoplane::name_of;
using monoplane::NameTable;
using monoplane::parse_name;

}  // namespace monoplane::modes
