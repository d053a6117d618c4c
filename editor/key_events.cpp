#include "editor/key_events.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <algorithm>
#include <utility>

namespace wg::editor {
namespace {

// One window per process: the queue and the callback it chains to.
std::vector<KeyPress> queuedPresses;
GLFWkeyfun chainedKeyCallback = nullptr;

void onKey(GLFWwindow* window, int key, int scancode, int action, int mods) {
  if (action == GLFW_PRESS || action == GLFW_REPEAT) queuedPresses.push_back({key, mods});
  if (chainedKeyCallback) chainedKeyCallback(window, key, scancode, action, mods);
}

}  // namespace

void installKeyQueue(GLFWwindow* window) {
  GLFWkeyfun previous = glfwSetKeyCallback(window, onKey);
  if (previous != onKey) chainedKeyCallback = previous;
  queuedPresses.clear();
}

std::vector<KeyPress> takeKeyPresses() { return std::exchange(queuedPresses, {}); }

bool wasPressed(const std::vector<KeyPress>& presses, int key, int mods) {
  constexpr int kCompared = GLFW_MOD_CONTROL | GLFW_MOD_SHIFT;
  return std::any_of(presses.begin(), presses.end(),
                     [&](const KeyPress& p) { return p.key == key && (p.mods & kCompared) == (mods & kCompared); });
}

}  // namespace wg::editor
