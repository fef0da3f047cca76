// ImageTexture: the footprint from a hit's uv derivatives, and loading a texture from a file.

#include <gtest/gtest.h>

#include <memory>

#include "TextureTestSupport.h"
#include "io/ImageReader.h"
#include "materials/BlinnPhongMaterial.h"
#include "materials/BumpMap.h"
#include "materials/CheckerTexture.h"
#include "materials/ImageTexture.h"
#include "materials/NormalMap.h"
#include "math/Srgb.h"
#include "scene/InputError.h"

namespace lancer {
namespace {

class ImageTextureTest : public testing::Test {
protected:
    // 32 x 32 texels, so 6 levels.
    std::shared_ptr<const MipMap> mipmap =
        std::make_shared<const MipMap>(test::makeImage(32, 32, [](int x, int y) {
            return Color(static_cast<float>(x % 7), static_cast<float>(y % 3), 1);
        }));
    ImageTexture texture{mipmap};
    static constexpr float kTexel = 1.0f / 32;

    Hit hitAt(Vec2 at, float dudx, float dvdx, float dudy, float dvdy) const {
        Hit hit;
        hit.setUv(at);
        hit.dudx = dudx;
        hit.dvdx = dvdx;
        hit.dudy = dudy;
        hit.dvdy = dvdy;
        return hit;
    }
    const Vec2 uv{0.42f, 0.77f};
};

TEST_F(ImageTextureTest, WithoutDerivativesReadsLevelZeroBilinearly) {
    EXPECT_EQ(texture.evaluate(hitAt(uv, 0, 0, 0, 0)), mipmap->bilinear(0, uv));
}

TEST_F(ImageTextureTest, FootprintOfOneTexelPerPixelReadsLevelZero) {
    EXPECT_EQ(texture.evaluate(hitAt(uv, kTexel, 0, 0, kTexel)), mipmap->bilinear(0, uv));
}

TEST_F(ImageTextureTest, FootprintIsTheLongerSideOfThePixel) {
    // One pixel covers 4 texels down the screen and half a texel across: level 2.
    EXPECT_EQ(texture.evaluate(hitAt(uv, kTexel / 2, 0, 0, 4 * kTexel)), mipmap->bilinear(2, uv));
    EXPECT_EQ(texture.evaluate(hitAt(uv, 0, -4 * kTexel, kTexel / 2, 0)), mipmap->bilinear(2, uv));
}

TEST_F(ImageTextureTest, FootprintMeasuresDiagonalDerivativesByTheirLength) {
    // (2, 2) texels per pixel: 2^1.5 texels, half-way between levels 1 and 2.
    const Color expected = (mipmap->bilinear(1, uv) + mipmap->bilinear(2, uv)) / 2;
    const Color actual = texture.evaluate(hitAt(uv, 2 * kTexel, 2 * kTexel, 0, 0));
    EXPECT_NEAR(actual.r, expected.r, 1e-4f);
    EXPECT_NEAR(actual.g, expected.g, 1e-4f);
    EXPECT_NEAR(actual.b, expected.b, 1e-4f);
}

TEST_F(ImageTextureTest, SharesItsMipMap) {
    const ImageTexture other(mipmap);
    EXPECT_EQ(&texture.mipmap(), &other.mipmap());
}

TEST_F(ImageTextureTest, MaterialsReadTheFootprintOnlyThroughAFilteredTextureOrABumpMap) {
    // (Whitted computes a hit's footprint only where it is read.)
    const auto image = std::make_shared<ImageTexture>(mipmap);
    const auto checker = std::make_shared<CheckerTexture>(Color(1), Color(0), 1);
    EXPECT_TRUE(image->readsFootprint());
    EXPECT_FALSE(checker->readsFootprint());
    EXPECT_FALSE(BlinnPhongMaterial().readsFootprint());
    BlinnPhongMaterial::Parameters checkered;
    checkered.diffuse = checker;
    EXPECT_FALSE(BlinnPhongMaterial(checkered).readsFootprint());
    BlinnPhongMaterial::Parameters glossyMap;
    glossyMap.specularMap = image;
    EXPECT_TRUE(BlinnPhongMaterial(glossyMap).readsFootprint());
    BlinnPhongMaterial bumped, mapped, mappedByChecker, cutOut;
    bumped.setShadingNormalMap(std::make_shared<BumpMap>(checker, 0.1f));
    EXPECT_TRUE(bumped.readsFootprint());
    mapped.setShadingNormalMap(std::make_shared<NormalMap>(image));
    EXPECT_TRUE(mapped.readsFootprint());
    mappedByChecker.setShadingNormalMap(std::make_shared<NormalMap>(checker));
    EXPECT_FALSE(mappedByChecker.readsFootprint());
    cutOut.setOpacity(image);
    EXPECT_TRUE(cutOut.readsFootprint());
}

TEST(ImageTextureLoadTest, LoadsAFileIntoAMipMap) {
    const test::TempFolder folder;
    const test::fs::path file = folder / "texture.png";
    test::save(test::makeBitmap8(4, 2, [](int x, int) { return test::rgb(x * 60, 0, 255); }), file,
               FIF_PNG);
    const std::shared_ptr<const ImageTexture> texture = ImageReader::readTexture(file);
    ASSERT_EQ(texture->mipmap().levelCount(), 3);
    Hit hit;
    hit.setUv({(2 + 0.5f) / 4, 0.25f});  // texel (2, 1)
    EXPECT_EQ(texture->evaluate(hit), Color(srgbToLinear(120 / 255.0f), 0, 1));
}

TEST(ImageTextureLoadTest, LoadsARealTextureOfOddWidth) {
    const std::shared_ptr<const ImageTexture> texture =
        ImageReader::readTexture(test::dataFolder() / "SpiderTex.jpg");
    const MipMap& mipmap = texture->mipmap();
    EXPECT_EQ(mipmap.image(0).width(), 249);
    EXPECT_EQ(mipmap.image(0).height(), 250);
    ASSERT_EQ(mipmap.levelCount(), 8);  // 250 -> 125 -> 62 -> 31 -> 15 -> 7 -> 3 -> 1
    EXPECT_EQ(mipmap.image(7).width(), 1);
    EXPECT_EQ(mipmap.image(7).height(), 1);
}

TEST(ImageTextureLoadTest, MissingFileIsAnInputErrorNamingIt) {
    const test::TempFolder folder;
    const test::fs::path file = folder / "missing.jpg";
    try {
        ImageReader::readTexture(file);
        FAIL() << "no error";
    } catch (const InputError& error) {
        EXPECT_NE(std::string(error.what()).find(file.string()), std::string::npos) << error.what();
    }
}

}  // namespace
}  // namespace lancer
