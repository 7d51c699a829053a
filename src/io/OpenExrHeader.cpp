#include "io/OpenExrHeader.h"

#include "io/ImageFile.h"

#include <OpenEXR/openexr.h>

#include <stdexcept>
#include <unistd.h>

namespace io {

namespace {

struct Source {
    int descriptor;
    std::int64_t size;
};

// The core library's first message for this thread's parse (it reports through a callback).
thread_local std::string firstMessage;

extern "C" void keepFirstMessage(exr_const_context_t, exr_result_t code, const char* message)
{
    if (firstMessage.empty())
        firstMessage =
            message != nullptr && *message != '\0' ? message : exr_get_default_error_message(code);
}

extern "C" int64_t readAt(exr_const_context_t, void* userData, void* buffer, uint64_t size,
                          uint64_t offset, exr_stream_error_func_ptr_t)
{
    const Source& source = *static_cast<const Source*>(userData);
    return ::pread(source.descriptor, buffer, size, static_cast<off_t>(offset));
}

extern "C" int64_t sizeOf(exr_const_context_t, void* userData)
{
    return static_cast<const Source*>(userData)->size;
}

}  // namespace

ImageLayout checkOpenExrHeader(std::FILE* file, std::int64_t fileSize, const std::string& name)
{
    Source source{::fileno(file), fileSize};
    exr_context_initializer_t initializer = EXR_DEFAULT_CONTEXT_INITIALIZER;
    initializer.user_data = &source;
    initializer.read_fn = readAt;
    initializer.size_fn = sizeOf;
    initializer.error_handler_fn = keepFirstMessage;
    initializer.max_image_width = kLargestSideRead;
    initializer.max_image_height = kLargestSideRead;
    initializer.max_tile_width = kLargestTileSideRead;
    initializer.max_tile_height = kLargestTileSideRead;
    initializer.flags = EXR_CONTEXT_FLAG_STRICT_HEADER;
    firstMessage.clear();
    exr_context_t context = nullptr;
    exr_result_t result = exr_start_read(&context, name.c_str(), &initializer);
    ImageLayout layout;
    exr_attr_box2i_t window{};
    const exr_attr_chlist_t* channels = nullptr;
    exr_storage_t storage = EXR_STORAGE_SCANLINE;
    if (result == EXR_ERR_SUCCESS)
        result = exr_get_data_window(context, 0, &window);
    if (result == EXR_ERR_SUCCESS)
        result = exr_get_channels(context, 0, &channels);
    if (result == EXR_ERR_SUCCESS)
        result = exr_get_storage(context, 0, &storage);
    if (result == EXR_ERR_SUCCESS) {
        layout.x = window.min.x;
        layout.y = window.min.y;
        layout.width = static_cast<std::int64_t>(window.max.x) - window.min.x + 1;
        layout.height = static_cast<std::int64_t>(window.max.y) - window.min.y + 1;
        layout.channels = channels->num_channels;
        for (int c = 0; c < channels->num_channels; ++c)
            layout.bytesPerPixel += channels->entries[c].pixel_type == EXR_PIXEL_HALF ? 2 : 4;
        layout.deep = storage == EXR_STORAGE_DEEP_SCANLINE || storage == EXR_STORAGE_DEEP_TILED;
        if (storage == EXR_STORAGE_TILED) {
            uint32_t tileWidth = 0;
            uint32_t tileHeight = 0;
            result = exr_get_tile_descriptor(context, 0, &tileWidth, &tileHeight, nullptr, nullptr);
            layout.tileWidth = static_cast<int>(tileWidth);
            layout.tileHeight = static_cast<int>(tileHeight);
        }
    }
    exr_finish(&context);
    if (result != EXR_ERR_SUCCESS)
        throw std::runtime_error(
            "cannot read image " + name + ": not a readable exr file (" +
            (firstMessage.empty() ? exr_get_default_error_message(result) : firstMessage) + ")");
    return layout;
}

}  // namespace io
