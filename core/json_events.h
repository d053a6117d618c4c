#pragma once
// A JSON file's events with the file position of every value and key (a valid file read
// in place by core/json_fast_read.h; nlohmann's SAX parse says what is wrong with any other),
// and the JSON-level checks every reader of a graph-shaped file wants: syntax (WG001), encoding (WG002: invalid
// UTF-8, a byte-order mark), duplicate keys (WG003, every duplicate, with the first
// occurrence as a note), a float literal beyond double (WG010) and nesting deeper than 64
// levels (WG035). A handler sees the events; it builds a DOM (core/json_source.h) or a
// Graph directly (core/graph_parse.cpp) without one.
#include <string>
#include <string_view>

#include "core/diagnostic.h"
#include "core/json_event_handler.h"

namespace wg {

// Feeds `text` to `handler`. False, with the diagnostics saying why, on any of the errors
// above; events already delivered stand, and the handler's result is not to be used.
bool parseJsonEvents(std::string_view text, const std::string& file, Diagnostics& diags, JsonEventHandler& handler);

}  // namespace wg
