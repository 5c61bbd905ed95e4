// LBNL's BSDF XML (WINDOW 6/7, genBSDF, the BSDF-v1.4 schema): the optical layer's Klems
// matrices (full, half and quarter bases) or its tensor tree (TensorTree3, TensorTree4), read
// into a Bsdf (engine/bsdf.h) with Radiance's rules (src/common/bsdf_m.c, bsdf_t.c): the XML's
// "Front" is the exterior, -z of the local frame; a missing transmission is the other one by
// reciprocity, a missing reflection is zero. Photopic data (CIE-Y, or "Visible" without a
// detector) is grey; where CIE-X and CIE-Z blocks are given too the three make the colour.
#pragma once

#include "engine/bsdf.h"

#include <filesystem>
#include <memory>
#include <string_view>

namespace candela {

// Sizes refused before anything is allocated.
inline constexpr size_t kMaxBsdfXmlBytes = size_t{256} << 20;  // 256 MiB
inline constexpr size_t kMaxKlemsPatches = 1000;               // a basis' patches (full: 145)
inline constexpr int kMaxTensorTreeDepth = 16;                 // a tree's levels

// Reads the file at `path`; InputError at "path:line" (the XML's line) with what is wrong.
std::shared_ptr<const Bsdf> readBsdfXml(const std::filesystem::path& path);
// The same from text already in memory; `name` stands for the file in messages.
std::shared_ptr<const Bsdf> parseBsdfXml(std::string_view text, const std::string& name);

}  // namespace candela
