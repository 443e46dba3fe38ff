// The shaders' shared constants come from one place: ShaderConstants, as a prelude inserted
// after each shader's #version line when it is loaded (embedded or overridden through
// OSG_FILE_PATH). No shader file repeats a constant or hard-codes the light count.
#include <gtest/gtest.h>

#include <osgShadowSilhouette/ShaderConstants>
#include <osgShadowSilhouette/SilhouetteShadowTechnique>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>

namespace {

namespace fs = std::filesystem;
using osgShadowSilhouette::SilhouetteShadowTechnique;

std::string shaderDir()
{
    const char* env = std::getenv("OSS_SOURCE_DIR");
    const fs::path root = env && *env ? fs::path(env) : fs::path(__FILE__).parent_path().parent_path().parent_path();
    return (root / "osgShadowSilhouette" / "shaders").string();
}

std::string readText(const fs::path& path)
{
    std::ifstream in(path);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

std::vector<std::string> lines(const std::string& text)
{
    std::vector<std::string> out;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) out.push_back(line);
    return out;
}

} // namespace

TEST(ShaderPrelude, NoShaderFileRepeatsAConstant)
{
    int files = 0;
    // The constants, the defaults of the defines the technique sets per view, and the shadow
    // maps' sampler type.
    const std::regex defines(
        R"(#define\s+(OSS_MAX_SCENE_LIGHTS|OSS_MAX_SHADOW_LIGHTS|OSS_MAX_SHADOW_SLOTS|OSS_NUM_SHADOW_SLOTS|OSS_SKIPPED_SLOTS|OSS_MAX_LIST_SLOTS|OSS_SHADOW_SAMPLER)\b)");
    const std::regex sizedByNumber(R"(oss_lightIndex\s*\[\s*\d+\s*\])");
    const std::regex clampedByNumber(R"(clamp\s*\(\s*oss_maskLight\s*,\s*0\s*,\s*\d+\s*\))");
    for (const fs::directory_entry& entry : fs::directory_iterator(shaderDir()))
    {
        if (entry.path().extension() != ".glsl") continue;
        ++files;
        const std::string text = readText(entry.path());
        const std::string name = entry.path().filename().string();
        std::smatch m;
        EXPECT_FALSE(std::regex_search(text, m, defines)) << name << " defines " << m.str(1) << " itself";
        EXPECT_FALSE(std::regex_search(text, sizedByNumber)) << name << " sizes oss_lightIndex with a number";
        EXPECT_FALSE(std::regex_search(text, clampedByNumber)) << name << " clamps a light index with a number";
    }
    EXPECT_GE(files, 10) << "the shader directory " << shaderDir();
}

// getShadowShaders() loads through the same path as the technique's own programs.
TEST(ShaderPrelude, LoadedShadersDefineTheConstantsAfterTheirVersionLine)
{
    osg::ref_ptr<SilhouetteShadowTechnique> technique = new SilhouetteShadowTechnique;
    for (SilhouetteShadowTechnique::Mode mode :
         {SilhouetteShadowTechnique::SHADOW_MAP, SilhouetteShadowTechnique::SILHOUETTE_MAP,
          SilhouetteShadowTechnique::HYBRID, SilhouetteShadowTechnique::SHADOW_VOLUME})
    {
        technique->setMode(mode);
        const std::vector<osg::ref_ptr<osg::Shader>> shaders = technique->getShadowShaders();
        ASSERT_FALSE(shaders.empty()) << SilhouetteShadowTechnique::modeName(mode);
        for (const osg::ref_ptr<osg::Shader>& shader : shaders)
        {
            const std::vector<std::string> text = lines(shader->getShaderSource());
            ASSERT_GE(text.size(), 4u) << shader->getName();
            EXPECT_EQ(text[0].rfind("#version", 0), 0u) << shader->getName() << ": the #version line stays first";
            const std::string define =
                "#define OSS_MAX_SCENE_LIGHTS " + std::to_string(osgShadowSilhouette::shader::MAX_SCENE_LIGHTS);
            auto at = std::find(text.begin(), text.end(), define);
            ASSERT_NE(at, text.end()) << shader->getName() << " lacks '" << define << "'";
            for (const char* defaulted : {"OSS_MAX_SHADOW_LIGHTS", "OSS_MAX_SHADOW_SLOTS", "OSS_NUM_SHADOW_SLOTS",
                                          "OSS_SKIPPED_SLOTS", "OSS_MAX_LIST_SLOTS"})
                EXPECT_NE(std::find(text.begin(), text.end(), std::string("#ifndef ") + defaulted), text.end())
                    << shader->getName() << " lacks the default of " << defaulted;
            auto line = std::find_if(at, text.end(), [](const std::string& l) { return l.rfind("#line", 0) == 0; });
            ASSERT_NE(line, text.end()) << shader->getName() << ": no #line after the prelude";
            EXPECT_EQ(*line, "#line 2") << shader->getName() << ": the file's second line keeps its number";
        }
    }
}
