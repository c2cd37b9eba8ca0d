// The one translation unit that compiles tinygltf's implementation. Images are never decoded (the scenes module
// keeps texture paths only), so stb_image is not needed: the target defines TINYGLTF_NO_STB_IMAGE,
// TINYGLTF_NO_STB_IMAGE_WRITE and TINYGLTF_NO_EXTERNAL_IMAGE for every file that includes tiny_gltf.h.
#define TINYGLTF_IMPLEMENTATION
#include <tiny_gltf.h>
