// Serializers that check what they read: a number that does not parse or lies outside the
// property's range (PropertyRanges) and an enum name the lookup does not know are reported
// with OSG_WARN, naming the class, the property and the value read, and the object keeps
// the value it had. Apart from that they read and write exactly like osgDB's
// PropByValSerializer and EnumSerializer, so files stay compatible with OSG's own wrappers.
//
// In a wrapper (REGISTER_OBJECT_WRAPPER body), one line per property:
//   OSS_ADD_PROPERTY(unsigned int, ShadowMapSize, 2048);
// and for an enum, with osgDB's ADD_ENUM_VALUE / END_ENUM_SERIALIZER:
//   OSS_BEGIN_ENUM_PROPERTY(Mode, SHADOW_MAP);
//       ADD_ENUM_VALUE(SHADOW_MAP); ...
//   END_ENUM_SERIALIZER();
#ifndef OSS_PLUGINS_CHECKEDSERIALIZERS_H
#define OSS_PLUGINS_CHECKEDSERIALIZERS_H

#include <osgShadowSilhouette/PropertyRanges>

#include <osg/Notify>
#include <osgDB/Serializer>

#include <cmath>
#include <type_traits>

#include <sstream>
#include <string>

namespace ossdb {

/** The osgDB serializer type of a property type (what osgDB::ClassInterface reports). */
template<typename P> struct SerializerType;
template<> struct SerializerType<bool> { static constexpr osgDB::BaseSerializer::Type value = osgDB::BaseSerializer::RW_BOOL; };
template<> struct SerializerType<int> { static constexpr osgDB::BaseSerializer::Type value = osgDB::BaseSerializer::RW_INT; };
template<> struct SerializerType<unsigned int> { static constexpr osgDB::BaseSerializer::Type value = osgDB::BaseSerializer::RW_UINT; };
template<> struct SerializerType<float> { static constexpr osgDB::BaseSerializer::Type value = osgDB::BaseSerializer::RW_FLOAT; };
template<> struct SerializerType<double> { static constexpr osgDB::BaseSerializer::Type value = osgDB::BaseSerializer::RW_DOUBLE; };

template<typename P>
std::string toText(const P& value)
{
    std::ostringstream s;
    s << value;
    return s.str();
}

inline std::string toText(bool value)
{
    return value ? "TRUE" : "FALSE";
}

/** "osgShadowSilhouette::SilhouetteShadowTechnique: Property " */
inline std::string propertyPrefix(const osg::Object& object, const std::string& property)
{
    return std::string(object.libraryName()) + "::" + object.className() + ": " + property + " ";
}

/** A PropByValSerializer that reads a numeric property strictly: a text value must be a
 *  whole number token ("12abc" and "abc" are refused, not read as 12 or 0), and a value
 *  outside the property's range (osgShadowSilhouette/PropertyRanges) is refused before it
 *  reaches the setter, so that no value wraps or is clamped quietly; either way the warning
 *  names the property, the value and the range, and the object keeps the value it had. */
template<typename C, typename P>
class CheckedSerializer : public osgDB::PropByValSerializer<C, P>
{
public:
    typedef osgDB::PropByValSerializer<C, P> ParentType;
    typedef typename ParentType::Getter Getter;
    typedef typename ParentType::Setter Setter;

    CheckedSerializer(const char* name, P def, Getter gf, Setter sf) : ParentType(name, def, gf, sf) {}

    bool read(osgDB::InputStream& is, osg::Object& obj) override
    {
        if (!is.isBinary() && !is.matchString(this->_name)) return true;
        P value{};
        std::string text;
        double number = 0.0;
        bool isNumber = true;
        if (is.isBinary() || std::is_same<P, bool>::value)
        {
            is >> value;
            text = toText(value);
            number = double(value);
        }
        else
        {
            is >> text;
            isNumber = osgShadowSilhouette::parseNumber(text, number);
        }
        if (is.getException()) return false;
        C& object = static_cast<C&>(obj);
        // Copies: UBSan reports member access through `this` inside the pointer-to-member call.
        const Getter getter = this->_getter;
        const Setter setter = this->_setter;
        const osgShadowSilhouette::NumericPropertyRange* range = osgShadowSilhouette::numericPropertyRange(this->_name);
        if (!isNumber || (range && !osgShadowSilhouette::inRange(*range, number)))
        {
            const osgShadowSilhouette::NumericPropertyRange any{this->_name.c_str(), -INFINITY, INFINITY, false, ""};
            OSG_WARN << osgShadowSilhouette::refusedValueMessage(std::string(obj.libraryName()) + "::" + obj.className(),
                                                                 range ? *range : any, text, isNumber,
                                                                 toText((object.*getter)()))
                     << std::endl;
            return true;
        }
        if (!is.isBinary() && !std::is_same<P, bool>::value) value = static_cast<P>(number);
        (object.*setter)(value);
        return true;
    }
};

/** An EnumSerializer that warns about names and numbers outside its lookup table instead of
 *  silently reading them as 0, and that may accept extra spellings through a parser. */
template<typename C, typename P>
class CheckedEnumSerializer : public osgDB::EnumSerializer<C, P, void>
{
public:
    typedef osgDB::EnumSerializer<C, P, void> ParentType;
    typedef typename ParentType::Getter Getter;
    typedef typename ParentType::Setter Setter;
    typedef bool (*Parser)(const std::string&, P&);

    CheckedEnumSerializer(const char* name, P def, Getter gf, Setter sf) : ParentType(name, def, gf, sf) {}

    /** Other spellings a file may use (e.g. a lowercase short name); the table's names are always accepted. */
    void setParser(Parser parser) { _parser = parser; }

    bool read(osgDB::InputStream& is, osg::Object& obj) override
    {
        P value = this->_defaultValue;
        bool known = false;
        std::string text;
        if (is.isBinary())
        {
            osgDB::IntLookup::Value number = 0;
            is >> number;
            text = toText(number);
            known = isValue(number);
            if (known) value = static_cast<P>(number);
        }
        else
        {
            if (!is.matchString(this->_name)) return true;
            is >> text;
            known = parse(text, value);
        }
        if (is.getException()) return false;
        if (!known)
        {
            OSG_WARN << propertyPrefix(obj, this->_name) << "'" << text << "' is unknown (one of"
                     << names() << "); using " << this->getString(this->_defaultValue) << std::endl;
        }
        set(static_cast<C&>(obj), value, text);
        return true;
    }

private:
    bool isValue(osgDB::IntLookup::Value number) const
    {
        const auto& values = this->_lookup.getValueToString();
        return values.find(number) != values.end();
    }

    bool parse(const std::string& text, P& value) const
    {
        const auto& names = this->_lookup.getStringToValue();
        auto it = names.find(text);
        if (it != names.end())
        {
            value = static_cast<P>(it->second);
            return true;
        }
        return _parser && _parser(text, value);
    }

    std::string names() const
    {
        std::string list;
        for (const auto& entry : this->_lookup.getValueToString()) list += " " + entry.second;
        return list;
    }

    void set(C& object, P value, const std::string& text)
    {
        const Setter setter = this->_setter;
        const Getter getter = this->_getter;
        (object.*setter)(value);
        const P kept = (object.*getter)();
        if (kept != value)
        {
            OSG_WARN << propertyPrefix(object, this->_name) << text << " is out of range; using "
                     << this->getString(kept) << std::endl;
        }
    }

    Parser _parser = nullptr;
};

} // namespace ossdb

/** One checked property: TYPE getPROP() const and void setPROP(TYPE) of MyClass. */
#define OSS_ADD_PROPERTY(TYPE, PROP, DEF)                                                                   \
    wrapper->addSerializer(new ossdb::CheckedSerializer<MyClass, TYPE>(#PROP, DEF, &MyClass::get##PROP,    \
                                                                       &MyClass::set##PROP),               \
                           ossdb::SerializerType<TYPE>::value)

/** A checked enum property MyClass::PROP; continue with ADD_ENUM_VALUE, end with END_ENUM_SERIALIZER. */
#define OSS_BEGIN_ENUM_PROPERTY(PROP, DEF)                                                                  \
    {                                                                                                       \
        typedef ossdb::CheckedEnumSerializer<MyClass, MyClass::PROP> MySerializer;                          \
        osg::ref_ptr<MySerializer> serializer =                                                             \
            new MySerializer(#PROP, MyClass::DEF, &MyClass::get##PROP, &MyClass::set##PROP)

#endif
