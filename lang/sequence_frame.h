/// @file lang/sequence_frame.h
/// @brief The frame of a sequence a model is compiled for: the values of the predefined names
/// `frame` and `time`. A model is compiled once per frame (`kerf render --frames`), so both
/// are plain numbers during lowering and fold like `pi`.
#pragma once

#include <cstdint>

namespace kerf {

struct SequenceFrame {
    /// The frame number; 0 when no sequence is rendered.
    int64_t frame = 0;
    /// (frame − first) / count of the whole sequence, in [0, 1); 0 when no sequence is rendered.
    double time = 0.0;
};

}  // namespace kerf
