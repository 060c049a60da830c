// An app written before Facet's public headers moved under facet/<library>/: compiled by the
// consumer test (consumer_project.cmake) against the installed package, so every old path it
// includes still reaches its header (cmake/forwarding_headers/, kept for one release) and still
// declares what the app used from it.
#include "facet/atomic_file.h"
#include "facet/content_hash.h"
#include "facet/frame_eviction.h"
#include "facet/frame_graph.h"
#include "facet/gl_backend.h"
#include "facet/package.h"
#include "facet/package_checks.h"
#include "facet/package_reader.h"
#include "facet/program_interface.h"
#include "facet/render_backend.h"
#include "facet/render_path.h"
#include "facet/runtime/post_settings.h"
#include "facet/runtime/scene.h"
#include "facet/shader_abi.h"
#include "facet/texture_checks.h"
#include "facet/vulkan_backend.h"

using facet::AtomicFile;
using facet::abi::kAttribPosition;
using facet::package::loadError;
using facet::package::Package;
using facet::package::PackageReader;
using facet::package::ProgramInterface;
using facet::runtime::adoptGlContext;
using facet::runtime::buildForwardPostGraph;
using facet::runtime::checkFrameTextures;
using facet::runtime::createVulkanBackend;
using facet::runtime::kContentHashSeed;
using facet::runtime::kEvictAfterFrames;
using facet::runtime::PostSettings;
using facet::runtime::RenderBackend;
using facet::runtime::Scene;
using facet::runtime::fg::PassDesc;
