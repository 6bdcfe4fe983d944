// Vertex inputs of scenes::Vertex (scenes/scene.h): 32 bytes.
layout(location = 0) in vec3 in_position;
layout(location = 1) in vec3 in_normal;
layout(location = 2) in vec4 in_albedo;  // R8G8B8A8_UNORM
layout(location = 3) in uint in_material;
