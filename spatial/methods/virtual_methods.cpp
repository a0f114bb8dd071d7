// The virtual family (virtual_shadow_map.h): virtual shadow maps at the single map's physical
// texels. vsm requests pages at the level each pixel's footprint asks for and drops the least
// requested when the pool is full; vsm-dynamic raises the LOD bias until the requests fit (UE5's
// dynamic resolution).
#include <stdexcept>
#include <string>

#include "lexel/spatial/methods/families.h"

namespace lexel::spatial {

namespace {

constexpr const char* kSakmary =
    "M. Sakmary, J. Ryan, J. Hall, A. Lustri, \"Virtual Shadow Maps\", GPU Zen 3, 2024";

MethodMatrix Virtual(const std::string& name, bool fitPool, const MethodContext& context) {
    if (!context.readback) throw std::invalid_argument(name + " needs the readback");
    VirtualMapOptions options;
    options.fitPool = fitPool;
    MethodMatrix m;
    m.virtualMap = BuildVirtualShadowMap(context.baseline, *context.readback, options);
    const VirtualMapLayout& layout = m.virtualMap->layout;
    m.matrix = layout.PageMatrix({layout.maxLevel, 0, 0});
    return m;
}

MethodDescriptor Pages(std::string name, std::string description, bool fitPool) {
    MethodInfo info{name,
                    std::move(description),
                    kSakmary,
                    MethodFamily::kVirtual,
                    {.virtualMap = true},
                    StorageModel::kVirtualLevels};
    return {std::move(info), [name, fitPool](const MethodContext& context) {
                return Virtual(name, fitPool, context);
            }};
}

}  // namespace

std::vector<MethodDescriptor> VirtualMethods() {
    return {
        Pages("vsm",
              "virtual shadow map: 16k² pages at the footprint's level, the single map's texels",
              false),
        Pages("vsm-dynamic", "vsm with the LOD bias raised until its pages fit the pool (UE5)",
              true),
    };
}

}  // namespace lexel::spatial
