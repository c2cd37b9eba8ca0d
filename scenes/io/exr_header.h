// A walk over an EXR file's header(s) before OpenEXR reads them: every attribute must fit in the file. OpenEXR
// 3.1 trusts an attribute's declared size (a string attribute claiming 2 GiB is grown to that size byte by
// byte, 2 GB and over a minute, before the read fails at the end of the file; an unknown type or a preview is
// allocated at its claimed size at once); this walk reads the headers as OpenEXR does and answers at once.
// It also sets OpenEXR's own image and tile size limits (65536 a side) for the process.
#pragma once
#include <filesystem>
#include "raster/simd/isa.h"

namespace scenes::io {
SHADOWLAB_ISA_BEGIN

// Throws IoError `FILE: header attribute 'NAME' (TYPE) declares N bytes, more than the M left in the file`
// when an attribute's size is negative or larger than the rest of the file. Files that are not EXR, or whose
// headers are malformed in any other way, pass: OpenEXR reports those itself.
void check_exr_header(const std::filesystem::path& path);

SHADOWLAB_ISA_END
}  // namespace scenes::io
