#pragma once
//! \file model_io.h
//! Model reading and writing chosen by file name extension. Read: `.zome.json` (also `.json`) and
//! `.vef`. Write also: `.glb`, `.obj` (with an `.mtl` beside it) and `.csv` (the parts list).
//! The CLI and the wasm session both come through here.

#include <string>
#include <string_view>
#include <vector>

#include "core/io/obj_export.h"
#include "core/zome/model.h"

namespace zomeify {

//! What the writers may vary (the CLI's --obj-units and --no-faces, the page's downloads).
struct WriteOptions
{
    ObjUnits obj_units = ObjUnits::Millimetres;
    bool vef_faces = true; //!< false: the VEF has balls and struts only
};

//! Reads a model file; InvalidInputError/IoError with a one-line message on failure.
//! `notes` (optional) receives what a person should know of the file (a VEF's strut ends without
//! a ball, vertices left out: vef.h).
ZomeModel read_model_file(const std::string& path, std::vector<std::string>* notes = nullptr);
//! Reads a model from bytes; `file_name` decides the format by its extension.
ZomeModel read_model_buffer(std::string_view bytes, const std::string& file_name,
                            std::vector<std::string>* notes = nullptr);
//! The model in the format named by the extension of `file_name`.
std::string write_model_buffer(const ZomeModel& model, const std::string& file_name, const WriteOptions& options = {});
void write_model_file(const std::string& path, const ZomeModel& model, const WriteOptions& options = {});
//! Throws the InvalidInputError write_model_file would for a file name whose format it cannot
//! write, before any work is done.
void check_writable_model_name(const std::string& path);

} // namespace zomeify
