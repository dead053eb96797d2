#include "core/io/model_io.h"

#include "core/base/errors.h"
#include "core/io/file_bytes.h"
#include "core/io/vef.h"
#include "core/io/zome_json.h"

namespace zomeify {

namespace {

enum class ModelFormat
{
    ZomeJson,
    Vef
};

ModelFormat format_of(const std::string& file_name)
{
    const std::string ext = model_extension(file_name);
    if (ext == ".zome.json" || ext == ".json")
        return ModelFormat::ZomeJson;
    if (ext == ".vef")
        return ModelFormat::Vef;
    throw InvalidInputError("'" + file_name + "': unknown model format '" + ext +
                            "' (expected .zome.json or .vef)");
}

} // namespace

ZomeModel read_model_buffer(std::string_view bytes, const std::string& file_name)
{
    switch (format_of(file_name))
    {
    case ModelFormat::ZomeJson:
        return read_zome_json(bytes);
    case ModelFormat::Vef:
        return read_vef(bytes);
    }
    throw InvalidInputError("unknown model format");
}

ZomeModel read_model_file(const std::string& path)
{
    format_of(path); // refuse unknown formats before reading the file
    return read_model_buffer(read_file_bytes(path), path);
}

std::string write_model_buffer(const ZomeModel& model, const std::string& file_name)
{
    switch (format_of(file_name))
    {
    case ModelFormat::ZomeJson:
        return write_zome_json(model);
    case ModelFormat::Vef:
        return write_vef(model);
    }
    throw InvalidInputError("unknown model format");
}

void write_model_file(const std::string& path, const ZomeModel& model)
{
    write_file_bytes(path, write_model_buffer(model, path));
}

} // namespace zomeify
