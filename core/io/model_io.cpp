#include "core/io/model_io.h"

#include "core/base/errors.h"
#include "core/io/file_bytes.h"
#include "core/io/glb_export.h"
#include "core/io/vef.h"
#include "core/io/zome_json.h"
#include "core/parts/parts_list.h"

namespace zomeify {

namespace {

enum class ModelFormat
{
    ZomeJson,
    Vef,
    Glb, // write only
    Obj, // write only, with an .mtl beside it
    Csv  // write only: the parts list
};

ModelFormat format_of(const std::string& file_name, bool writing)
{
    const std::string ext = model_extension(file_name);
    if (ext == ".zome.json" || ext == ".json")
        return ModelFormat::ZomeJson;
    if (ext == ".vef")
        return ModelFormat::Vef;
    if (writing && ext == ".glb")
        return ModelFormat::Glb;
    if (writing && ext == ".obj")
        return ModelFormat::Obj;
    if (writing && ext == ".csv")
        return ModelFormat::Csv;
    throw InvalidInputError("'" + file_name + "': unknown model format '" + ext + "' (expected " +
                            (writing ? ".zome.json, .vef, .glb, .obj or .csv)" : ".zome.json or .vef)"));
}

// "dir/model.obj" -> "model.mtl"
std::string mtl_file_name(const std::string& obj_path)
{
    const size_t slash = obj_path.find_last_of("/\\");
    const std::string name = obj_path.substr(slash == std::string::npos ? 0 : slash + 1);
    return name.substr(0, name.size() - 4) + ".mtl";
}

} // namespace

ZomeModel read_model_buffer(std::string_view bytes, const std::string& file_name, std::vector<std::string>* notes)
{
    switch (format_of(file_name, false))
    {
    case ModelFormat::ZomeJson:
        return read_zome_json(bytes);
    case ModelFormat::Vef:
    {
        VefReadInfo info;
        ZomeModel model = read_vef(bytes, &info);
        if (notes)
            *notes = std::move(info.notes);
        return model;
    }
    default:
        break;
    }
    throw InvalidInputError("unknown model format");
}

ZomeModel read_model_file(const std::string& path, std::vector<std::string>* notes)
{
    format_of(path, false); // refuse unknown formats before reading the file
    return read_model_buffer(read_file_bytes(path), path, notes);
}

std::string write_model_buffer(const ZomeModel& model, const std::string& file_name, const WriteOptions& options)
{
    switch (format_of(file_name, true))
    {
    case ModelFormat::ZomeJson:
        return write_zome_json(model);
    case ModelFormat::Vef:
        return write_vef(model, VefWriteOptions{options.vef_faces});
    case ModelFormat::Glb:
        return write_glb(model);
    case ModelFormat::Obj:
        return write_obj(model, mtl_file_name(file_name), options.obj_units).obj;
    case ModelFormat::Csv:
        return parts_csv(parts_list(model));
    }
    throw InvalidInputError("unknown model format");
}

void check_writable_model_name(const std::string& path) { (void)format_of(path, true); }

void write_model_file(const std::string& path, const ZomeModel& model, const WriteOptions& options)
{
    if (format_of(path, true) == ModelFormat::Obj)
    {
        const ObjExport out = write_obj(model, mtl_file_name(path), options.obj_units);
        write_file_bytes(path, out.obj);
        write_file_bytes(path.substr(0, path.size() - 4) + ".mtl", out.mtl);
        return;
    }
    write_file_bytes(path, write_model_buffer(model, path, options));
}

} // namespace zomeify
