// The library's code keeps a shape a reader can follow (docs/architecture.md): no function
// body over 60 lines. A function here is a brace block opened after a closing parenthesis
// (with const, override, noexcept or a trailing return type between) outside any other
// function; lambdas and blocks inside a function count toward it.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

constexpr std::size_t MAX_FUNCTION_LINES = 60;

fs::path libraryDir()
{
    const char* env = std::getenv("OSS_SOURCE_DIR");
    const fs::path root = env && *env ? fs::path(env) : fs::path(__FILE__).parent_path().parent_path().parent_path();
    return root / "osgShadowSilhouette";
}

/** The line without its // comment and with its string and character literals emptied. */
std::string code(const std::string& line)
{
    std::string out;
    char quote = 0;
    for (std::size_t i = 0; i < line.size(); ++i)
    {
        const char c = line[i];
        if (quote)
        {
            if (c == '\\')
                ++i;
            else if (c == quote)
                quote = 0, out += c;
            continue;
        }
        if (c == '/' && i + 1 < line.size() && line[i + 1] == '/') break;
        if (c == '"' || c == '\'') quote = c;
        out += c;
    }
    return out;
}

struct LongFunction
{
    std::string where;
    std::size_t lines;
};

/** The functions of @p file longer than MAX_FUNCTION_LINES (C++ sources and headers). */
std::vector<LongFunction> longFunctions(const fs::path& file)
{
    static const std::regex opensFunction(R"(\)\s*(const|override|noexcept|final|\s)*(->[^{;]*)?\s*$)");
    std::ifstream in(file);
    std::vector<std::string> text;
    for (std::string line; std::getline(in, line);) text.push_back(code(line));
    std::vector<LongFunction> found;
    std::vector<bool> stack; // per open brace: whether it opens a function
    std::size_t start = 0;
    bool inComment = false;
    std::string before; // the code before the current character since the last ; { or }
    for (std::size_t n = 0; n < text.size(); ++n)
    {
        const std::string& line = text[n];
        for (std::size_t i = 0; i < line.size(); ++i)
        {
            if (inComment)
            {
                if (line.compare(i, 2, "*/") == 0) inComment = false, ++i;
                continue;
            }
            if (line.compare(i, 2, "/*") == 0)
            {
                inComment = true, ++i;
                continue;
            }
            const char c = line[i];
            if (c == '{')
            {
                const bool inFunction = std::find(stack.begin(), stack.end(), true) != stack.end();
                const bool function = !inFunction && std::regex_search(before, opensFunction);
                if (function) start = n;
                stack.push_back(function);
                before.clear();
            }
            else if (c == '}')
            {
                if (!stack.empty() && stack.back() && n - start + 1 > MAX_FUNCTION_LINES)
                    found.push_back({file.filename().string() + ":" + std::to_string(start + 1), n - start + 1});
                if (!stack.empty()) stack.pop_back();
                before.clear();
            }
            else if (c == ';')
                before.clear();
            else
                before += c;
        }
        before += ' ';
    }
    return found;
}

} // namespace

TEST(CodeShape, NoFunctionOfTheLibraryIsOverSixtyLines)
{
    const fs::path dir = libraryDir();
    ASSERT_TRUE(fs::is_directory(dir)) << dir;
    std::size_t files = 0;
    std::string report;
    for (const fs::directory_entry& entry : fs::directory_iterator(dir))
    {
        if (!entry.is_regular_file() || entry.path().extension() == ".txt") continue;
        ++files;
        for (const LongFunction& f : longFunctions(entry.path()))
            report += "  " + f.where + ": " + std::to_string(f.lines) + " lines\n";
    }
    EXPECT_GT(files, 20u) << "the library's sources were not found in " << dir;
    EXPECT_TRUE(report.empty()) << "functions over " << MAX_FUNCTION_LINES << " lines:\n" << report;
}

TEST(CodeShape, TheCheckFindsALongFunction)
{
    // A function of 61 lines, with a lambda and a string holding a brace, and a class and a
    // namespace around a short one: only the long function is reported.
    const fs::path file = fs::temp_directory_path() / "oss_code_shape_probe.cpp";
    {
        std::ofstream out(file);
        out << "namespace n {\nstruct S\n{\n    int f() const { return 1; }\n};\n}\n";
        out << "void longOne(int a)\n{\n    auto l = [&](int b) {\n        return b + a;\n    };\n";
        for (int i = 0; i < 55; ++i) out << "    l(" << i << "); // {\n";
        out << "    const char* s = \"}\";\n}\n";
    }
    const std::vector<LongFunction> found = longFunctions(file);
    fs::remove(file);
    ASSERT_EQ(found.size(), 1u);
    EXPECT_EQ(found[0].where, "oss_code_shape_probe.cpp:8");
    EXPECT_EQ(found[0].lines, 61u);
}
