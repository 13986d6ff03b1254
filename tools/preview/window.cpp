#include "tools/preview/window.h"

#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>

#include <algorithm>

#include "engine/core/error.h"
#include "engine/gpu/vk_check.h"

namespace mvpl::preview {
namespace {

Window* self(GLFWwindow* w) {
    return static_cast<Window*>(glfwGetWindowUserPointer(w));
}

std::string glfw_error() {
    const char* text = nullptr;
    glfwGetError(&text);
    return text ? text : "unknown GLFW error";
}

}  // namespace

Window::Window(const std::string& title, int width, int height) {
    if (!glfwInit()) {
        throw UsageError("preview: cannot open a window (" + glfw_error() +
                         "); is DISPLAY set? (headless: run it under xvfb-run)");
    }
    if (!glfwVulkanSupported()) {
        glfwTerminate();
        throw UsageError("preview: GLFW finds no Vulkan loader");
    }
    glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);
    glfwWindowHint(GLFW_RESIZABLE, GLFW_TRUE);
    m_window = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
    if (!m_window) {
        const std::string error = glfw_error();
        glfwTerminate();
        throw UsageError("preview: cannot create a window: " + error);
    }
    glfwSetWindowUserPointer(m_window, this);
    glfwSetKeyCallback(m_window, [](GLFWwindow* w, int key, int, int action, int mods) {
        self(w)->on_key(key, action, mods);
    });
    glfwSetCursorPosCallback(m_window,
                             [](GLFWwindow* w, double x, double y) { self(w)->on_cursor(x, y); });
    glfwSetScrollCallback(m_window,
                          [](GLFWwindow* w, double, double dy) { self(w)->on_scroll(dy); });
    glfwSetDropCallback(m_window, [](GLFWwindow* w, int count, const char** paths) {
        self(w)->on_drop(count, paths);
    });
}

Window::~Window() {
    glfwDestroyWindow(m_window);
    glfwTerminate();
}

std::vector<std::string> Window::required_instance_extensions() {
    uint32_t count = 0;
    const char** names = glfwGetRequiredInstanceExtensions(&count);
    if (!names) throw UsageError("preview: GLFW cannot present with Vulkan: " + glfw_error());
    return std::vector<std::string>(names, names + count);
}

bool Window::can_present(VkInstance instance, VkPhysicalDevice device, uint32_t queue_family) {
    return glfwGetPhysicalDevicePresentationSupport(instance, device, queue_family) == GLFW_TRUE;
}

VkSurfaceKHR Window::create_surface(VkInstance instance) const {
    VkSurfaceKHR surface = VK_NULL_HANDLE;
    gpu::vk_check(glfwCreateWindowSurface(instance, m_window, nullptr, &surface),
                  "glfwCreateWindowSurface");
    return surface;
}

void Window::poll() {
    glfwPollEvents();
    const auto held = [this](int key) { return glfwGetKey(m_window, key) == GLFW_PRESS ? 1 : 0; };
    m_input.fly_forward = held(GLFW_KEY_W) - held(GLFW_KEY_S);
    m_input.fly_right = held(GLFW_KEY_D) - held(GLFW_KEY_A);
    m_input.fly_up = held(GLFW_KEY_E) - held(GLFW_KEY_Q);
}

Input Window::take_input() {
    Input input = std::move(m_input);
    m_input = Input{};
    m_input.fly_forward = input.fly_forward;
    m_input.fly_right = input.fly_right;
    m_input.fly_up = input.fly_up;
    return input;
}

bool Window::close_requested() const {
    return glfwWindowShouldClose(m_window);
}

void Window::framebuffer_size(uint32_t& width, uint32_t& height) const {
    int w = 0, h = 0;
    glfwGetFramebufferSize(m_window, &w, &h);
    width = uint32_t(std::max(w, 0));
    height = uint32_t(std::max(h, 0));
}

void Window::set_size(int width, int height) {
    glfwSetWindowSize(m_window, width, height);
}

void Window::set_title(const std::string& title) {
    glfwSetWindowTitle(m_window, title.c_str());
}

void Window::wait(double seconds) {
    glfwWaitEventsTimeout(seconds);
}

void Window::on_key(int key, int action, int) {
    if (action != GLFW_PRESS) return;
    switch (key) {
        case GLFW_KEY_R:
            m_input.keys.push_back("r");
            break;
        case GLFW_KEY_EQUAL:
        case GLFW_KEY_KP_ADD:
            m_input.keys.push_back("plus");
            break;
        case GLFW_KEY_MINUS:
        case GLFW_KEY_KP_SUBTRACT:
            m_input.keys.push_back("minus");
            break;
        case GLFW_KEY_M:
            m_input.keys.push_back("m");
            break;
        case GLFW_KEY_C:
            m_input.keys.push_back("c");
            break;
        case GLFW_KEY_P:
            m_input.keys.push_back("p");
            break;
        case GLFW_KEY_V:
            m_input.keys.push_back("v");
            break;
        case GLFW_KEY_TAB:
            m_input.keys.push_back("tab");
            break;
        case GLFW_KEY_ESCAPE:
            m_input.keys.push_back("escape");
            break;
        default:
            break;
    }
}

void Window::on_cursor(double x, double y) {
    const float dx = m_cursor_known ? float(x - m_cursor_x) : 0.0f;
    const float dy = m_cursor_known ? float(y - m_cursor_y) : 0.0f;
    m_cursor_x = x;
    m_cursor_y = y;
    m_cursor_known = true;
    const bool left = glfwGetMouseButton(m_window, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS;
    const bool middle = glfwGetMouseButton(m_window, GLFW_MOUSE_BUTTON_MIDDLE) == GLFW_PRESS;
    const bool right = glfwGetMouseButton(m_window, GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS;
    const bool shift = glfwGetKey(m_window, GLFW_KEY_LEFT_SHIFT) == GLFW_PRESS ||
                       glfwGetKey(m_window, GLFW_KEY_RIGHT_SHIFT) == GLFW_PRESS;
    if (middle || (left && shift)) {
        m_input.pan_x += dx;
        m_input.pan_y += dy;
    } else if (left) {
        m_input.orbit_x += dx;
        m_input.orbit_y += dy;
    } else if (right) {
        m_input.look_x += dx;
        m_input.look_y += dy;
    }
}

void Window::on_scroll(double dy) {
    m_input.wheel += float(dy);
}

void Window::on_drop(int count, const char** paths) {
    for (int i = 0; i < count; ++i)
        m_input.drops.emplace_back(paths[i]);
}

}  // namespace mvpl::preview
