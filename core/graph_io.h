#pragma once
// Graph files for the layers above core (nodes, codegen, cli, editor, tests): reading one
// file (core/graph_parse.h), loading a graph with its imports (core/graph_load.h) and
// writing the canonical form (core/graph_save.h). Inside core, include the one you call:
// the import loader includes graph_parse.h alone, below graph_load.h, and a file of core
// including this header would put it above graph_load (tests/core/core_layering_test.cpp).
#include "core/graph_load.h"
#include "core/graph_parse.h"
#include "core/graph_save.h"
