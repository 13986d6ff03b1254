#pragma once
// Accessor reading that trusts nothing in the file: every index, offset, stride and count is
// checked against the buffers before a byte is read or an element allocated.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "engine/core/math.h"
#include "engine/scene/gltf_document.h"

namespace mvpl::scene::gltf {

// What a use of an accessor demands of it.
struct AccessorNeeds {
    std::string usage;                 // for messages, e.g. "POSITION of mesh 2 primitive 0"
    int type = TINYGLTF_TYPE_SCALAR;   // TINYGLTF_TYPE_*
    std::vector<int> component_types;  // TINYGLTF_COMPONENT_TYPE_* allowed
    bool integers_normalized = false;  // integer components must be normalized (TEXCOORD)
};

// A validated accessor: reading it cannot leave its buffer.
class AccessorView {
public:
    AccessorView(const Document& doc, int index, AccessorNeeds needs);

    size_t count() const { return m_count; }
    int index() const { return m_index; }
    const std::string& label() const { return m_label; }
    const std::string& usage() const { return m_usage; }

    // Components as floats; normalized integers are mapped to [0, 1] (or [-1, 1]).
    std::vector<Vec2> read_vec2() const;
    std::vector<Vec3> read_vec3() const;
    std::vector<Vec4> read_vec4() const;
    // Unsigned integer scalars (indices).
    std::vector<uint32_t> read_uints() const;

private:
    struct Sparse {
        size_t count = 0;
        const unsigned char* indices = nullptr;
        int index_component_type = 0;
        const unsigned char* values = nullptr;
    };

    template <int N>
    std::vector<glm::vec<N, float>> read_floats() const;
    // Calls visit(element index, pointer to its bytes) for every element, sparse
    // substitutions last so that they win.
    template <typename Visit>
    void for_each_element(Visit&& visit) const;
    // m_data and m_stride: the accessor's elements in its buffer view, checked to fit.
    void locate_data(const tinygltf::Accessor& accessor);
    // m_sparse: the accessor's sparse substitutions, checked.
    void read_sparse(const tinygltf::Accessor& accessor);
    const unsigned char* view_bytes(int view_index, size_t offset, size_t count,
                                    size_t element_size, size_t stride,
                                    const std::string& what) const;

    const Document& m_doc;
    int m_index = -1;
    std::string m_label;
    std::string m_usage;
    size_t m_count = 0;
    int m_component_type = 0;
    int m_components = 1;
    size_t m_element_size = 0;
    bool m_normalized = false;
    const unsigned char* m_data = nullptr;  // null: no buffer view, all zeros
    size_t m_stride = 0;
    Sparse m_sparse;
};

}  // namespace mvpl::scene::gltf
