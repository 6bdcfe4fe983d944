// Every file of scenes/gltf includes tinygltf through here, so all of them see the same
// configuration (the TinyGLTF class's members depend on it). tinygltf's own image decoding and
// writing are off: images are kept encoded and only the base-colour images a scene uses are
// decoded (texture_decode.h), with size limits, by a private copy of stb_image; nothing here
// defines stb symbols another target could collide with.
#pragma once

#ifndef TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE
#endif
#ifndef TINYGLTF_NO_STB_IMAGE_WRITE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#endif

#include <tiny_gltf.h>
