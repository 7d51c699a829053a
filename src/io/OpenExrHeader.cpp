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
        firstMessage = message != nullptr && *message != '\0'
                           ? message
                           : exr_get_default_error_message(code);
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

void checkOpenExrHeader(std::FILE* file, std::int64_t fileSize, const std::string& name)
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
    const exr_result_t result = exr_start_read(&context, name.c_str(), &initializer);
    exr_finish(&context);
    if (result != EXR_ERR_SUCCESS)
        throw std::runtime_error("cannot read image " + name + ": not a readable exr file (" +
                                 (firstMessage.empty() ? exr_get_default_error_message(result)
                                                       : firstMessage) +
                                 ")");
}

}  // namespace io
