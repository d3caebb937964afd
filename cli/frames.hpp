// Animation frames (POV-Ray 3.7's rules): which frames to render, each frame's clock and
// scene identifiers, and the output file name (numbered in animations).
#pragma once
#include <string>
#include <vector>

#include "cli/options.hpp"

namespace lumen::cli {

struct Frame {
    int number = 0;              // frame_number seen by the scene (0 for a still image)
    std::string output;          // file to write (empty with -F)
    interp::InterpOptions scene; // options for interpreting this frame
};

// True when Final_Frame > Initial_Frame.
bool is_animation(const Options& o);

// The frames to render, in order: one for a still image.
std::vector<Frame> plan_frames(const Options& o);

// The file extension lumen writes for a file type (".png", ...).
std::string extension_for(render::FileType type);

// The output path: +O as given (a folder when it ends in '/', with the type's extension added
// when it has none), else the input's base name in the current folder; in animations the frame
// number, zero-padded to the digit count of the final frame, goes before the extension.
std::string output_path(const Options& o, int frame);

}  // namespace lumen::cli
