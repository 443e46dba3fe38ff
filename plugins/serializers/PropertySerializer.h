// The serializer of one row of the table of properties (osgShadowSilhouette/Properties).
//
// It reads and writes exactly as osgDB's PropByValSerializer (BOOL, INT, UINT, FLOAT) and
// EnumSerializer (ENUM) of the property's type would, so files stay compatible with OSG's
// own wrappers: in .osgt/.osgx a line "Name value" where the value is not the default, in
// .osgb the value in the type's binary form. What it reads goes through the table's strict
// parser: a number that does not parse or lies outside the range, an enum name or boolean the
// table does not know, is reported with OSG_WARN naming the class, the property, the value
// and what the property takes, and the object keeps the value it had.
#ifndef OSS_PLUGINS_PROPERTYSERIALIZER_H
#define OSS_PLUGINS_PROPERTYSERIALIZER_H

#include <osgShadowSilhouette/Properties>
#include <osgShadowSilhouette/SilhouetteShadowTechnique>

#include <osg/Notify>
#include <osgDB/InputStream>
#include <osgDB/OutputStream>
#include <osgDB/Serializer>

#include <string>

namespace ossdb {

class PropertySerializer : public osgDB::BaseSerializer
{
public:
    using Info = osgShadowSilhouette::PropertyInfo;
    using Technique = osgShadowSilhouette::SilhouetteShadowTechnique;

    explicit PropertySerializer(const Info& info)
        : osgDB::BaseSerializer(READ_WRITE_PROPERTY), _info(info), _name(info.name)
    {
        for (const osgShadowSilhouette::PropertyEnumValue& e : info.enumValues) _lookup.add(e.name, e.value);
    }

    /** The osgDB type of the property (what osgDB::ClassInterface reports). */
    static Type typeOf(const Info& info)
    {
        switch (info.type)
        {
        case Info::BOOL: return RW_BOOL;
        case Info::INT: return RW_INT;
        case Info::UINT: return RW_UINT;
        case Info::FLOAT: return RW_FLOAT;
        default: return RW_ENUM;
        }
    }

    const std::string& getName() const override { return _name; }
    osgDB::IntLookup* getIntLookup() override { return _info.type == Info::ENUM ? &_lookup : nullptr; }

    bool read(osgDB::InputStream& is, osg::Object& obj) override
    {
        std::string text;
        if (is.isBinary())
            text = readBinary(is);
        else if (!is.matchString(_name))
            return true;
        else
            is >> text;
        if (is.getException()) return false;
        Technique& technique = static_cast<Technique&>(obj);
        double value = 0.0;
        std::string error;
        if (osgShadowSilhouette::parsePropertyValue(_info, text, value, error))
        {
            _info.set(technique, value);
            return true;
        }
        OSG_WARN << obj.libraryName() << "::" << obj.className() << ": " << _name << " " << text << " " << error
                 << "; keeping " << osgShadowSilhouette::formatPropertyValue(_info, _info.get(technique)) << std::endl;
        return true;
    }

    bool write(osgDB::OutputStream& os, const osg::Object& obj) override
    {
        const double value = _info.get(static_cast<const Technique&>(obj));
        if (os.isBinary())
        {
            writeBinary(os, value);
            return true;
        }
        if (same(value, _info.defaultValue)) return true;
        os << os.PROPERTY(_name.c_str());
        if (_info.type == Info::ENUM)
            os << _lookup.getString(static_cast<int>(value));
        else
            writeBinary(os, value); // the ascii writer formats the typed value
        os << std::endl;
        return true;
    }

private:
    /** The value of the stream's binary form, as text the table's parser reads. */
    std::string readBinary(osgDB::InputStream& is) const
    {
        switch (_info.type)
        {
        case Info::BOOL:
        {
            bool v = false;
            is >> v;
            return v ? "TRUE" : "FALSE";
        }
        case Info::INT:
        {
            int v = 0;
            is >> v;
            return std::to_string(v);
        }
        case Info::UINT:
        {
            unsigned int v = 0;
            is >> v;
            return std::to_string(v);
        }
        case Info::FLOAT:
        {
            float v = 0.0f;
            is >> v;
            return osgShadowSilhouette::formatPropertyValue(_info, v);
        }
        default:
        {
            osgDB::IntLookup::Value v = 0;
            is >> v;
            return enumText(v);
        }
        }
    }

    /** An enum's name, or its number when the table has no such value (the parser refuses it). */
    std::string enumText(osgDB::IntLookup::Value v) const
    {
        const auto& names = _lookup.getValueToString();
        const auto it = names.find(v);
        return it != names.end() ? it->second : std::to_string(v);
    }

    void writeBinary(osgDB::OutputStream& os, double value) const
    {
        switch (_info.type)
        {
        case Info::BOOL: os << (value != 0.0); break;
        case Info::INT: os << static_cast<int>(value); break;
        case Info::UINT: os << static_cast<unsigned int>(value); break;
        case Info::FLOAT: os << static_cast<float>(value); break;
        default: os << static_cast<osgDB::IntLookup::Value>(value); break;
        }
    }

    /** Whether two values are the same in the property's type (a float's default is a float). */
    bool same(double a, double b) const { return _info.type == Info::FLOAT ? float(a) == float(b) : a == b; }

    const Info& _info;
    std::string _name;
    osgDB::IntLookup _lookup;
};

} // namespace ossdb

#endif
