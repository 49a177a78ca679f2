// The key codes of the demo's bindings (app/demo: the window's and the page's keys). They are GLFW's
// (printable keys are their upper-case ASCII code); glfw_window.cpp checks them against GLFW's header.
#pragma once

namespace shadelab {

inline constexpr int kKeySpace = 32;
inline constexpr int kKeyEscape = 256;
inline constexpr int kKeyBackspace = 259;
inline constexpr int kKeyRight = 262;
inline constexpr int kKeyLeft = 263;
inline constexpr int kKeyPageUp = 266;
inline constexpr int kKeyPageDown = 267;
inline constexpr int kKeyHome = 268;
inline constexpr int kKeyEnd = 269;
inline constexpr int kKeyF1 = 290;
inline constexpr int kKeyF2 = 291;
inline constexpr int kKeyF11 = 300;
inline constexpr int kKeyKeypadSubtract = 333;
inline constexpr int kKeyKeypadAdd = 334;

} // namespace shadelab
