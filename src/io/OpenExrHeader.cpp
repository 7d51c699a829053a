#include "io/OpenExrHeader.h"

#include <stdexcept>

namespace io {

namespace {

class HeaderReader {
public:
    HeaderReader(std::FILE* file, std::int64_t size, const std::string& name)
        : file_(file), left_(size), name_(name)
    {
    }

    [[noreturn]] void refuse(const std::string& why) const
    {
        throw std::runtime_error("cannot read image " + name_ + ": not a readable exr file (" +
                                 why + ")");
    }

    int byte()
    {
        const int value = left_ > 0 ? std::fgetc(file_) : EOF;
        if (value == EOF)
            refuse("its header is cut short");
        --left_;
        return value;
    }

    std::uint32_t word()
    {
        std::uint32_t value = 0;
        for (int shift = 0; shift < 32; shift += 8)
            value |= static_cast<std::uint32_t>(byte()) << shift;
        return value;
    }

    // A name or type ending with a zero byte, at most `longest` bytes before it.
    std::string text(std::size_t longest)
    {
        std::string value;
        for (int c; (c = byte()) != 0;) {
            if (value.size() == longest)
                refuse("a name in its header is longer than " + std::to_string(longest) +
                       " bytes");
            value += static_cast<char>(c);
        }
        return value;
    }

    void skip(std::int64_t count)
    {
        if (count > left_ || std::fseek(file_, static_cast<long>(count), SEEK_CUR) != 0)
            refuse("an attribute says it holds " + std::to_string(count) + " bytes, more than "
                   "the " + std::to_string(left_) + " left in the file");
        left_ -= count;
    }

private:
    std::FILE* file_;
    std::int64_t left_;
    const std::string& name_;
};

}  // namespace

void checkOpenExrHeader(std::FILE* file, std::int64_t fileSize, const std::string& name)
{
    HeaderReader header(file, fileSize, name);
    if (header.word() != 20000630u)
        header.refuse("it does not begin with OpenEXR's magic number");
    const std::uint32_t version = header.word();
    const bool longNames = (version & 0x400u) != 0;
    const bool multipart = (version & 0x1000u) != 0;
    const std::size_t longest = longNames ? 255 : 31;
    for (int part = 0;; ++part) {
        int attributes = 0;
        for (std::string attribute; !(attribute = header.text(longest)).empty(); ++attributes) {
            header.text(longest);  // the type
            const auto size = static_cast<std::int32_t>(header.word());
            if (size < 0)
                header.refuse("the attribute " + attribute + " says its size is negative");
            header.skip(size);
        }
        // A multi-part file's headers end with an empty one.
        if (!multipart || attributes == 0)
            break;
    }
    std::rewind(file);
}

}  // namespace io
