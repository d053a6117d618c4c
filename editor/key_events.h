#pragma once
// Shortcuts as events, not per-frame polls: the window's key callback keeps every press
// until the frame takes it, so a tap shorter than a frame (pressed and released between two
// polls, on a slow frame) still counts. ImGui 1.86's keys are a per-frame state
// (io.KeysDown): a press released before the next frame is never seen there.
#include <vector>

struct GLFWwindow;

namespace wg::editor {

struct KeyPress {
  int key = 0;   // GLFW_KEY_*
  int mods = 0;  // GLFW_MOD_* held with it
};

// Chains a callback after the one installed on `window` (ImGui's, which keeps working).
void installKeyQueue(GLFWwindow* window);
// The presses (and repeats) since the last call, in order.
std::vector<KeyPress> takeKeyPresses();

// Whether `presses` holds `key` with exactly the Ctrl and Shift of `mods` (other modifiers
// ignored).
bool wasPressed(const std::vector<KeyPress>& presses, int key, int mods = 0);

}  // namespace wg::editor
