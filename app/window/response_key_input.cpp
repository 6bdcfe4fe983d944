#include "app/window/response_key_input.h"

#include <GLFW/glfw3.h>

#include <array>

namespace monoplane::window {
namespace {

struct NamedKey {
    std::string_view name;
    int key;
};

// Every name of study/response_keys.cpp whose GLFW key is not derived from its spelling below
// (letters, digits, F-keys and keypad digits are).
constexpr NamedKey kNamedKeys[] = {
    {"Left", GLFW_KEY_LEFT},
    {"Right", GLFW_KEY_RIGHT},
    {"Up", GLFW_KEY_UP},
    {"Down", GLFW_KEY_DOWN},
    {"Return", GLFW_KEY_ENTER},
    {"KP_Enter", GLFW_KEY_KP_ENTER},
    {"space", GLFW_KEY_SPACE},
    {"Tab", GLFW_KEY_TAB},
    {"BackSpace", GLFW_KEY_BACKSPACE},
    {"Home", GLFW_KEY_HOME},
    {"End", GLFW_KEY_END},
    {"Prior", GLFW_KEY_PAGE_UP},
    {"Next", GLFW_KEY_PAGE_DOWN},
    {"Insert", GLFW_KEY_INSERT},
    {"Delete", GLFW_KEY_DELETE},
    {"KP_Add", GLFW_KEY_KP_ADD},
    {"KP_Subtract", GLFW_KEY_KP_SUBTRACT},
    {"KP_Multiply", GLFW_KEY_KP_MULTIPLY},
    {"KP_Divide", GLFW_KEY_KP_DIVIDE},
    {"KP_Decimal", GLFW_KEY_KP_DECIMAL},
    {"comma", GLFW_KEY_COMMA},
    {"period", GLFW_KEY_PERIOD},
    {"slash", GLFW_KEY_SLASH},
    {"semicolon", GLFW_KEY_SEMICOLON},
    {"minus", GLFW_KEY_MINUS},
    {"equal", GLFW_KEY_EQUAL},
    {"Shift_L", GLFW_KEY_LEFT_SHIFT},
    {"Shift_R", GLFW_KEY_RIGHT_SHIFT},
    {"Control_L", GLFW_KEY_LEFT_CONTROL},
    {"Control_R", GLFW_KEY_RIGHT_CONTROL},
    {"Alt_L", GLFW_KEY_LEFT_ALT},
    {"Alt_R", GLFW_KEY_RIGHT_ALT},
};

// F1..F25 are consecutive in GLFW; "F" followed by 1 to 12 here.
std::optional<int> function_key(std::string_view name) {
    if (name.size() < 2 || name.size() > 3 || name[0] != 'F') return std::nullopt;
    int n = 0;
    for (char c : name.substr(1)) {
        if (c < '0' || c > '9') return std::nullopt;
        n = n * 10 + (c - '0');
    }
    if (n < 1 || n > 12 || name[1] == '0') return std::nullopt;
    return GLFW_KEY_F1 + n - 1;
}

}  // namespace

std::optional<int> glfw_key_for(std::string_view name) {
    for (const NamedKey& named : kNamedKeys)
        if (named.name == name) return named.key;
    // GLFW's letter keys are the upper-case ASCII codes, its digit keys the digits'.
    if (name.size() == 1 && name[0] >= 'a' && name[0] <= 'z') return GLFW_KEY_A + (name[0] - 'a');
    if (name.size() == 1 && name[0] >= '0' && name[0] <= '9') return GLFW_KEY_0 + (name[0] - '0');
    if (name.size() == 4 && name.substr(0, 3) == "KP_" && name[3] >= '0' && name[3] <= '9') {
        return GLFW_KEY_KP_0 + (name[3] - '0');
    }
    return function_key(name);
}

const ResponseKeyBinding* find_binding(const std::vector<ResponseKeyBinding>& bindings,
                                       int glfw_key) {
    for (const ResponseKeyBinding& binding : bindings)
        if (binding.glfw_key == glfw_key) return &binding;
    return nullptr;
}

}  // namespace monoplane::window
