// Quality presets shared by the case file, the command line and the tracer.
#pragma once

#include <string>

namespace candela {

enum class Quality { kDraft, kNormal, kHigh };

const char* qualityName(Quality q);
// Parses "draft", "normal" or "high"; throws std::invalid_argument otherwise.
Quality parseQuality(const std::string& s);

}  // namespace candela
