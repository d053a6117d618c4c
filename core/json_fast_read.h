#pragma once
// The JSON reader for well-formed files (internal to core/json_events.cpp): the same events,
// positions and values nlohmann's SAX parse gives a valid file (numbers typed as its lexer
// types them, strings decoded alike), read from the bytes in place. nlohmann's lexer reads a
// byte at a time through an input adapter and a position counter, and was most of a large
// graph's load; this reader is three to four times faster.
// It reports nothing: at the first thing a valid file may not hold (a syntax error, invalid
// UTF-8, a duplicate key, a number beyond double, nesting deeper than the limit) it stops and
// returns false, and parseJsonEvents reads the file again with nlohmann's parser, which says
// what is wrong in the words every diagnostic of the format has always used.
#include <string_view>

#include "core/json_event_handler.h"

namespace wg {

// True when `text` is one valid JSON value (surrounded by whitespace only) within the depth
// limit and without duplicate keys, every event delivered to `handler`. False otherwise,
// with some events delivered: the handler's result is then not to be used.
bool readWellFormedJsonEvents(std::string_view text, JsonEventHandler& handler);

}  // namespace wg
