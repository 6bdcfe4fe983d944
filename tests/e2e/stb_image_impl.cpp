// stb_image, compiled once for the end-to-end tests that read PNGs back.
#define STB_IMAGE_IMPLEMENTATION
#include <stb/stb_image.h>
