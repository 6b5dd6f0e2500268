#include "render/texture_readback.hpp"

namespace strata {

Image readRgbaTexture(GLuint texture, glm::ivec2 size) {
    Image image(size.x, size.y);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glGetTextureImage(texture, 0, GL_RGBA, GL_FLOAT, GLsizei(image.rgba.size() * sizeof(float)), image.rgba.data());
    return image;
}

}  // namespace strata
