#include <osgShadowSilhouette/PropertyRanges>
#include <osgShadowSilhouette/Properties>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <sstream>

namespace osgShadowSilhouette {

const std::vector<NumericPropertyRange>& numericPropertyRanges()
{
    static const std::vector<NumericPropertyRange> ranges = [] {
        std::vector<NumericPropertyRange> numeric;
        for (const PropertyInfo& p : properties())
            if (p.numeric()) numeric.push_back({p.name, p.min, p.max, p.type != PropertyInfo::FLOAT, p.rangeNote});
        return numeric;
    }();
    return ranges;
}

const NumericPropertyRange* numericPropertyRange(const std::string& name)
{
    for (const NumericPropertyRange& r : numericPropertyRanges())
        if (name == r.name) return &r;
    return nullptr;
}

std::string describeRange(const NumericPropertyRange& range)
{
    std::ostringstream s;
    if (std::isinf(range.min) && std::isinf(range.max)) s << "any finite number";
    else if (std::isinf(range.max)) s << "at least " << range.min;
    else s << range.min << " to " << range.max;
    if (range.integer && !(std::isinf(range.min) && std::isinf(range.max))) s << ", whole";
    if (*range.note) s << ": " << range.note;
    return s.str();
}

bool inRange(const NumericPropertyRange& range, double value)
{
    return std::isfinite(value) && value >= range.min && value <= range.max &&
           (!range.integer || std::floor(value) == value);
}

bool parseNumber(const std::string& text, double& value)
{
    if (text.empty() || std::isspace(static_cast<unsigned char>(text.front()))) return false;
    if (text.find_first_of("xXpP") != std::string::npos) return false; // strtod's hexadecimal forms
    errno = 0;
    char* end = nullptr;
    const double v = std::strtod(text.c_str(), &end);
    if (end != text.c_str() + text.size() || errno == ERANGE || !std::isfinite(v)) return false;
    value = v;
    return true;
}

std::string refusedValueMessage(const std::string& where, const NumericPropertyRange& range, const std::string& text,
                                bool isNumber, const std::string& kept)
{
    return where + ": " + range.name + " " + text + (isNumber ? " is out of range (" : " is not a finite number (") +
           describeRange(range) + "); keeping " + kept;
}

}
