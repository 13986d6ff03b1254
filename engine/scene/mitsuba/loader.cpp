// load_mitsuba (scene_loader.h): a Mitsuba 3 or 0.6 XML scene walked top-down, each plugin read
// by its own file here (shapes, bsdfs, textures, emitters, sensor).
#include <pugixml.hpp>

#include "engine/core/error.h"
#include "engine/scene/camera.h"
#include "engine/scene/mitsuba/bsdfs.h"
#include "engine/scene/mitsuba/emitters.h"
#include "engine/scene/mitsuba/properties.h"
#include "engine/scene/mitsuba/sensor.h"
#include "engine/scene/mitsuba/shapes.h"
#include "engine/scene/mitsuba/xml_files.h"
#include "engine/scene/scene_loader.h"
#include "engine/scene/scene_range.h"

namespace mvpl::scene {

namespace {

using mitsuba::Context;

// The material of a shape: its BSDF (or Mitsuba's default diffuse), made emissive by an `area`
// emitter (a copy per emissive shape, so that the BSDF's other users stay dark).
int shape_material(Context& ctx, pugi::xml_node shape) {
    const std::vector<pugi::xml_node> bsdfs = ctx.objects(shape, "bsdf");
    if (bsdfs.size() > 1) ctx.fail(bsdfs[1], "a shape takes one bsdf");
    int material = bsdfs.empty() ? mitsuba::default_material_index(ctx)
                                 : mitsuba::material_index(ctx, bsdfs.front());
    for (pugi::xml_node child : ctx.xml().children(shape)) {
        const std::string tag = child.name();
        if (tag == "medium" ||
            (tag == "ref" && (std::string(child.attribute("name").as_string()) == "interior" ||
                              std::string(child.attribute("name").as_string()) == "exterior")))
            ctx.fail(child, "participating media are not supported");
    }
    const std::vector<pugi::xml_node> emitters = ctx.objects(shape, "emitter");
    if (emitters.size() > 1) ctx.fail(emitters[1], "a shape takes one emitter");
    if (!emitters.empty()) {
        Material emissive = ctx.scene().materials[size_t(material)];
        emissive.emissive = mitsuba::area_radiance(ctx, emitters.front());
        emissive.emissive_strength = 1.0f;
        if (pugi::xml_attribute id = shape.attribute("id"))
            emissive.name = std::string(id.value()) + " (emitter)";
        ctx.scene().materials.push_back(emissive);
        material = int(ctx.scene().materials.size()) - 1;
    }
    return material;
}

void read_scene(Context& ctx) {
    const pugi::xml_node root = ctx.xml().root();
    ctx.index_ids(root);
    for (pugi::xml_node child : ctx.xml().children(root)) {
        const std::string tag = child.name();
        if (tag == "shape") {
            mitsuba::add_shape(ctx, child, DMat4(1.0),
                               [&ctx](pugi::xml_node shape) { return shape_material(ctx, shape); });
        } else if (tag == "emitter") {
            // An area emitter at the top level exists to be referenced from shapes.
            if (std::string(child.attribute("type").as_string()) != "area")
                mitsuba::add_emitter(ctx, child);
        } else if (tag == "sampler" || tag == "film" || tag == "rfilter") {
            ctx.warn(child, "a top-level " + tag + " is dropped (mvpl's command line sets it)");
        } else if (tag == "sensor") {
            mitsuba::add_sensor(ctx, child);
        } else if (tag == "integrator") {
            mitsuba::read_integrator(ctx, child);
        } else if (tag == "bsdf" || tag == "texture") {
            continue;  // read where a shape refers to it
        } else if (tag == "medium" || tag == "phase" || tag == "volume") {
            ctx.fail(child, tag + " (participating media) is not supported");
        } else {
            ctx.fail(child, "<" + tag + "> is not supported at the scene's top level");
        }
    }
}

}  // namespace

Scene load_mitsuba(const std::string& path, const LoadOptions& options) {
    const mitsuba::XmlFiles xml(path, options);
    Scene scene;
    scene.path = path;
    Context ctx(xml, scene);
    read_scene(ctx);
    if (scene.meshes.empty()) throw InputError(path, "the scene has no shapes");
    if (scene.materials.empty()) mitsuba::default_material_index(ctx);
    if (!scene.has_camera) {
        scene.camera = frame_bounds(scene.bounds());
    }
    check_emitted_power(
        scene, [&](int light) { return "emitter '" + scene.lights[size_t(light)].name + "'"; },
        [&](int material) { return "material '" + scene.materials[size_t(material)].name + "'"; },
        [&](const std::string& what) { throw InputError(path, what); });
    return scene;
}

}  // namespace mvpl::scene
