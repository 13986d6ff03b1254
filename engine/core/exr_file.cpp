#include "engine/core/exr_file.h"

#include <ImfChannelList.h>
#include <ImfChromaticitiesAttribute.h>
#include <ImfDoubleAttribute.h>
#include <ImfFloatAttribute.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfIntAttribute.h>
#include <ImfOutputFile.h>
#include <ImfStandardAttributes.h>
#include <ImfStringAttribute.h>

#include <cstdio>
#include <set>
#include <stdexcept>

#include "engine/core/error.h"
#include "engine/core/image.h"
#include "engine/core/regular_file.h"

namespace mvpl {

namespace {

// ITU-R BT.709 primaries and the D65 white point (CIE xy), OpenEXR's default chromaticities,
// written explicitly so that a reader need not know the default.
Imf::Chromaticities rec709() {
    return Imf::Chromaticities(Imath::V2f(0.64f, 0.33f), Imath::V2f(0.30f, 0.60f),
                               Imath::V2f(0.15f, 0.06f), Imath::V2f(0.3127f, 0.3290f));
}

void check_layers(const Image& image, const ExrExtras& extras) {
    std::set<std::string> names{"R", "G", "B"};
    for (const ChannelImage& layer : extras.layers) {
        const size_t pixels = size_t(image.width()) * size_t(image.height());
        if (layer.width != image.width() || layer.height != image.height() ||
            layer.values.size() != pixels * layer.channels.size())
            throw std::invalid_argument("EXR layer " + layer.name + " is not the image's size");
        for (const std::string& c : layer.channels) {
            if (c.empty() || !names.insert(c).second)
                throw std::invalid_argument("EXR channel '" + c + "' given twice or empty");
        }
    }
}

void add_attribute(Imf::Header& header, const ExrAttribute& a) {
    if (const auto* s = std::get_if<std::string>(&a.value)) {
        header.insert(a.name, Imf::StringAttribute(*s));
    } else if (const auto* i = std::get_if<int>(&a.value)) {
        header.insert(a.name, Imf::IntAttribute(*i));
    } else {
        header.insert(a.name, Imf::DoubleAttribute(std::get<double>(a.value)));
    }
}

std::string number_text(double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.17g", v);
    return buf;
}

std::string attribute_text(const Imf::Attribute& a) {
    if (const auto* s = dynamic_cast<const Imf::StringAttribute*>(&a)) return s->value();
    if (const auto* i = dynamic_cast<const Imf::IntAttribute*>(&a))
        return std::to_string(i->value());
    if (const auto* d = dynamic_cast<const Imf::DoubleAttribute*>(&a))
        return number_text(d->value());
    if (const auto* f = dynamic_cast<const Imf::FloatAttribute*>(&a))
        return number_text(f->value());
    if (const auto* c = dynamic_cast<const Imf::ChromaticitiesAttribute*>(&a)) {
        const Imf::Chromaticities& v = c->value();
        std::string text;
        const std::pair<const char*, Imath::V2f> points[] = {
            {"R", v.red}, {"G", v.green}, {"B", v.blue}, {"W", v.white}};
        for (const auto& [label, p] : points) {
            text += std::string(text.empty() ? "" : " ") + label + " " + number_text(p.x) + " " +
                    number_text(p.y);
        }
        return text;
    }
    return a.typeName();
}

}  // namespace

void write_exr_file(const Image& image, const ExrExtras& extras, const std::string& file) {
    check_layers(image, extras);
    Imf::Header header(image.width(), image.height());
    Imf::addChromaticities(header, rec709());
    for (const ExrAttribute& a : extras.attributes)
        add_attribute(header, a);
    Imf::FrameBuffer fb;
    char* base = reinterpret_cast<char*>(const_cast<Rgb*>(image.pixels().data()));
    const size_t xs = sizeof(Rgb);
    const size_t ys = sizeof(Rgb) * size_t(image.width());
    const char* rgb[3] = {"R", "G", "B"};
    for (int c = 0; c < 3; ++c) {
        header.channels().insert(rgb[c], Imf::Channel(Imf::FLOAT));
        fb.insert(rgb[c], Imf::Slice(Imf::FLOAT, base + size_t(c) * sizeof(float), xs, ys));
    }
    for (const ChannelImage& layer : extras.layers) {
        const size_t n = layer.channels.size();
        char* values = reinterpret_cast<char*>(const_cast<float*>(layer.values.data()));
        for (size_t c = 0; c < n; ++c) {
            header.channels().insert(layer.channels[c], Imf::Channel(Imf::FLOAT));
            fb.insert(layer.channels[c],
                      Imf::Slice(Imf::FLOAT, values + c * sizeof(float), n * sizeof(float),
                                 n * sizeof(float) * size_t(layer.width)));
        }
    }
    Imf::OutputFile out(file.c_str(), header);
    out.setFrameBuffer(fb);
    out.writePixels(image.height());
}

const std::vector<float>* ExrContents::channel(const std::string& name) const {
    for (const auto& [n, values] : channels) {
        if (n == name) return &values;
    }
    return nullptr;
}

std::string ExrContents::attribute(const std::string& name) const {
    for (const auto& [n, text] : attributes) {
        if (n == name) return text;
    }
    return {};
}

bool ExrContents::has_attribute(const std::string& name) const {
    for (const auto& a : attributes) {
        if (a.first == name) return true;
    }
    return false;
}

ExrContents read_exr_file(const std::string& path) {
    require_regular_file(path);
    try {
        Imf::InputFile file(path.c_str());
        const Imf::Header& header = file.header();
        const Imath::Box2i dw = header.dataWindow();
        ExrContents out;
        out.width = dw.max.x - dw.min.x + 1;
        out.height = dw.max.y - dw.min.y + 1;
        if (out.width <= 0 || out.height <= 0 || int64_t(out.width) * out.height > (1 << 28))
            throw InputError(path, "EXR has an unusable size");
        const size_t pixels = size_t(out.width) * size_t(out.height);
        for (auto it = header.channels().begin(); it != header.channels().end(); ++it)
            out.channels.emplace_back(it.name(), std::vector<float>(pixels));
        Imf::FrameBuffer fb;
        const size_t ys = sizeof(float) * size_t(out.width);
        // OpenEXR addresses a slice by absolute data-window coordinates.
        const ptrdiff_t origin =
            -ptrdiff_t(dw.min.x) * ptrdiff_t(sizeof(float)) - ptrdiff_t(dw.min.y) * ptrdiff_t(ys);
        for (auto& [name, values] : out.channels) {
            char* base = reinterpret_cast<char*>(values.data()) + origin;
            fb.insert(name, Imf::Slice(Imf::FLOAT, base, sizeof(float), ys));
        }
        file.setFrameBuffer(fb);
        file.readPixels(dw.min.y, dw.max.y);
        for (auto it = header.begin(); it != header.end(); ++it)
            out.attributes.emplace_back(it.name(), attribute_text(it.attribute()));
        return out;
    } catch (const InputError&) {
        throw;
    } catch (const std::exception& e) {
        throw InputError(path, std::string("cannot read EXR: ") + e.what());
    }
}

}  // namespace mvpl
