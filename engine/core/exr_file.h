#pragma once
// OpenEXR files with more than the beauty image: extra channels (the AOVs of engine/aov) and header
// attributes. Every EXR mvpl writes says what its RGB is: the standard `chromaticities` attribute
// holds Rec. 709 primaries with the D65 white point (the linear RGB of docs/design.md, "Units and
// conventions"), so that tools which read it (OpenImageIO, Nuke, OCIO configs) need no guess.
// Attributes of our own are named "mvpl/…" (as Arnold's are "arnold/…"); see README, "Outputs".
#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace mvpl {

class Image;

// Named channels of one width × height image, interleaved per pixel: values[(y · width + x) · C +
// c] is channels[c], C = channels.size(), row 0 at the top. Channel names are the file's, whole
// ("albedo.R", "Z").
struct ChannelImage {
    std::string name;  // what the image is called outside a file (an AOV's name)
    std::vector<std::string> channels;
    int width = 0;
    int height = 0;
    std::vector<float> values;
};

// A header attribute: text, a 32-bit integer or a double.
struct ExrAttribute {
    std::string name;
    std::variant<std::string, int, double> value;
};

// What an EXR holds besides R, G, B and the chromaticities.
struct ExrExtras {
    std::vector<ChannelImage> layers;
    std::vector<ExrAttribute> attributes;
};

// Writes `image` as float R, G, B, the extras' channels and attributes, and the Rec. 709
// chromaticities into `file` (not atomically: write_images in image.h is the atomic writer).
// Throws std::invalid_argument for a layer of another size than the image or a channel name given
// twice (R, G and B included); OpenEXR's exception for an attribute named as a standard one of
// another type.
void write_exr_file(const Image& image, const ExrExtras& extras, const std::string& file);

// Every channel (as float) and every attribute (as text) of an EXR: for tests and tools that
// look at more than the beauty image (read_exr in image.h reads R, G, B).
struct ExrContents {
    int width = 0;
    int height = 0;
    std::vector<std::pair<std::string, std::vector<float>>> channels;  // in the file's order
    // Text: strings as they are; numbers in full precision; chromaticities as
    // "R rx ry G gx gy B bx by W wx wy"; other types by their type name.
    std::vector<std::pair<std::string, std::string>> attributes;

    // Null or empty where the file has none of that name.
    const std::vector<float>* channel(const std::string& name) const;
    std::string attribute(const std::string& name) const;
    bool has_attribute(const std::string& name) const;
};
// Throws InputError naming the file.
ExrContents read_exr_file(const std::string& path);

}  // namespace mvpl
