#pragma once
// `compile --textures`: the node textures a graph samples, written beside its shaders as
// PNG files so that clients without watergraph's C++ (the three.js client, an engine)
// upload exactly the texels the runtime does. Built-in procedural textures are generated
// here, by the same code the runtime and the CPU reference use, so there is one source.
#include <vector>

#include "codegen/compile.h"
#include "core/diagnostic.h"

namespace wg {

// The file name a texture of the manifest is written under: "<graph>.<sampler>.png",
// e.g. "waves.t0_foam.png", where <graph> names the shader files too; the manifest records
// it as each node texture's "file" (buildManifest), and textureFiles writes that name.
std::string textureFileName(const std::string& graphName, const std::string& sampler);

// One PNG per manifest texture with a "source" (scene resources have none), named by its
// "file": rows top to
// bottom as in any PNG, so the first row of the GL texture (v = 0) is the picture's bottom
// row, exactly as a PNG source file is read. A texture that cannot be decoded is WG030 at
// the option naming it (at the node without `graph`), naming the node; the returned list is
// then incomplete and must not be written.
std::vector<OutputFile> textureFiles(const CompileResult& result, Diagnostics& diags, const Graph* graph = nullptr);

// Reports texture `source` of the compiled graph as unusable (`why`): WG030 at the option
// naming it (at the node without `graph`), naming the node. For the runtime's
// rt::TextureLoadError too, so `render` and `check` say what `compile --textures` says.
void reportUnusableTexture(const Program& program, const Graph* graph, const std::string& source,
                           const std::string& why, Diagnostics& diags);

}  // namespace wg
