#include "vtkSubDGLTFCheck.h"

#include "vtk_jsoncpp.h"

#include <cstdint>
#include <cstring>
#include <fstream>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace
{
using Size = std::uint64_t;

struct Problem : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

std::string ReadAll(const std::string& path, bool& ok)
{
  std::ifstream in(path, std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  ok = static_cast<bool>(in);
  return bytes.str();
}

// Size of a file, or -1 when it cannot be opened.
long long FileSize(const std::string& path)
{
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  return in ? static_cast<long long>(in.tellg()) : -1;
}

std::uint32_t Word(const std::string& bytes, std::size_t at)
{
  std::uint32_t value = 0;
  for (int i = 3; i >= 0; --i)
  {
    value = (value << 8) | static_cast<unsigned char>(bytes[at + i]);
  }
  return value;
}

// The JSON text and the size of the binary chunk of a .glb (0 if it has none), or the whole
// text of a .gltf.
std::string JsonText(const std::string& bytes, Size& binarySize)
{
  binarySize = 0;
  if (bytes.size() < 4 || bytes.compare(0, 4, "glTF") != 0)
  {
    return bytes;
  }
  if (bytes.size() < 20 || Word(bytes, 4) != 2)
  {
    throw Problem("a binary glTF (.glb) needs version 2 and a JSON chunk");
  }
  const Size jsonSize = Word(bytes, 12);
  if (Word(bytes, 16) != 0x4E4F534Au || 20 + jsonSize > bytes.size())
  {
    throw Problem("the JSON chunk of the .glb is missing or longer than the file");
  }
  const Size binaryAt = 20 + ((jsonSize + 3) / 4) * 4;
  if (binaryAt + 8 <= bytes.size() && Word(bytes, binaryAt + 4) == 0x004E4942u)
  {
    binarySize = Word(bytes, binaryAt);
    if (binaryAt + 8 + binarySize > bytes.size())
    {
      throw Problem("the binary chunk of the .glb is longer than the file");
    }
  }
  return bytes.substr(20, jsonSize);
}

const Json::Value& Array(const Json::Value& object, const char* key)
{
  static const Json::Value empty(Json::arrayValue);
  if (!object.isMember(key))
  {
    return empty;
  }
  if (!object[key].isArray())
  {
    throw Problem(std::string("'") + key + "' is not an array");
  }
  return object[key];
}

Size Number(const Json::Value& object, const char* key, Size fallback, const std::string& where)
{
  if (!object.isMember(key))
  {
    return fallback;
  }
  const Json::Value& value = object[key];
  if (!value.isIntegral() || value.asLargestInt() < 0)
  {
    throw Problem(where + ": '" + key + "' is not a non-negative integer");
  }
  // Counts and byte sizes up to a terabyte: the sums and products of the checks below cannot
  // overflow, which a hostile file's huge values would make them do.
  if (value.asLargestUInt() > (Size(1) << 40))
  {
    throw Problem(where + ": '" + key + "' is larger than a file this reader takes");
  }
  return value.asLargestUInt();
}

// Checks that object[key], when present, indexes root[collection]; returns it (or -1 if absent).
long long Reference(const Json::Value& root, const Json::Value& object, const char* key, const char* collection,
  const std::string& where)
{
  if (!object.isObject() || !object.isMember(key))
  {
    return -1;
  }
  const Size index = Number(object, key, 0, where);
  if (index >= Array(root, collection).size())
  {
    throw Problem(where + ": '" + key + "' refers to " + collection + "[" + std::to_string(index) + "], and there are " +
      std::to_string(Array(root, collection).size()));
  }
  return static_cast<long long>(index);
}

std::string Item(const char* collection, Json::ArrayIndex i)
{
  return std::string(collection) + "[" + std::to_string(i) + "]";
}

struct Checker
{
  const Json::Value& Root;
  std::string Directory;
  Size BinarySize;
  std::vector<Size> BufferLengths;
  std::vector<Size> ViewLengths;

  // A data: URI's decoded length, or the length of the file it names.
  Size UriLength(const std::string& uri, const std::string& where) const
  {
    if (uri.compare(0, 5, "data:") == 0)
    {
      const auto comma = uri.find(";base64,");
      if (comma == std::string::npos)
      {
        throw Problem(where + ": only base64 data URIs are read");
      }
      Size chars = uri.size() - comma - 8;
      Size padding = 0;
      while (padding < 2 && chars > 0 && uri[comma + 8 + chars - 1 - padding] == '=')
      {
        ++padding;
      }
      return chars / 4 * 3 - padding;
    }
    const std::string path = (!uri.empty() && uri[0] == '/') ? uri : this->Directory + uri;
    const long long size = FileSize(path);
    if (size < 0)
    {
      throw Problem(where + ": cannot open '" + path + "'");
    }
    return static_cast<Size>(size);
  }

  void Buffers()
  {
    const Json::Value& buffers = Array(this->Root, "buffers");
    for (Json::ArrayIndex i = 0; i < buffers.size(); ++i)
    {
      const std::string where = Item("buffers", i);
      const Size length = Number(buffers[i], "byteLength", 0, where);
      Size available = this->BinarySize;
      if (buffers[i].isMember("uri"))
      {
        if (!buffers[i]["uri"].isString())
        {
          throw Problem(where + ": 'uri' is not a string");
        }
        available = this->UriLength(buffers[i]["uri"].asString(), where);
      }
      else if (i != 0)
      {
        throw Problem(where + " has no 'uri' (only the first buffer may be a .glb's binary chunk)");
      }
      if (length == 0 || length > available)
      {
        throw Problem(where + " declares " + std::to_string(length) + " bytes and holds " + std::to_string(available));
      }
      this->BufferLengths.push_back(length);
    }
  }

  void BufferViews()
  {
    const Json::Value& views = Array(this->Root, "bufferViews");
    for (Json::ArrayIndex i = 0; i < views.size(); ++i)
    {
      const std::string where = Item("bufferViews", i);
      const long long buffer = Reference(this->Root, views[i], "buffer", "buffers", where);
      const Size offset = Number(views[i], "byteOffset", 0, where);
      const Size length = Number(views[i], "byteLength", 0, where);
      if (buffer < 0 || offset + length > this->BufferLengths[buffer])
      {
        throw Problem(where + " lies outside its buffer");
      }
      this->ViewLengths.push_back(length);
    }
  }

  static Size ComponentSize(Size type)
  {
    switch (type)
    {
      case 5120: case 5121: return 1;
      case 5122: case 5123: return 2;
      case 5125: case 5126: return 4;
      default: return 0;
    }
  }

  static Size ComponentCount(const std::string& type)
  {
    static const char* const names[] = { "SCALAR", "VEC2", "VEC3", "VEC4", "MAT2", "MAT3", "MAT4" };
    static const Size counts[] = { 1, 2, 3, 4, 4, 9, 16 };
    for (int i = 0; i < 7; ++i)
    {
      if (type == names[i])
      {
        return counts[i];
      }
    }
    return 0;
  }

  void Accessors()
  {
    const Json::Value& accessors = Array(this->Root, "accessors");
    const Json::Value& views = Array(this->Root, "bufferViews");
    for (Json::ArrayIndex i = 0; i < accessors.size(); ++i)
    {
      const Json::Value& accessor = accessors[i];
      const std::string where = Item("accessors", i);
      const Size component = ComponentSize(Number(accessor, "componentType", 0, where));
      const Size components = ComponentCount(accessor.get("type", "").asString());
      const Size count = Number(accessor, "count", 0, where);
      if (component == 0 || components == 0 || count == 0)
      {
        throw Problem(where + ": needs a known 'componentType' and 'type' and a 'count' of at least 1");
      }
      if (accessor.isMember("sparse") || !accessor.isMember("bufferView"))
      {
        throw Problem(where + ": sparse accessors and accessors without a buffer view are not read");
      }
      const long long view = Reference(this->Root, accessor, "bufferView", "bufferViews", where);
      const Size element = component * components;
      const Size stride = Number(views[static_cast<Json::ArrayIndex>(view)], "byteStride", element, where);
      const Size end = Number(accessor, "byteOffset", 0, where) + (count - 1) * stride + element;
      if (stride < element || stride > 252 || end > this->ViewLengths[view]) // (glTF: strides up to 252)
      {
        throw Problem(where + " reads past the end of its buffer view");
      }
    }
  }

  void Meshes()
  {
    const Json::Value& meshes = Array(this->Root, "meshes");
    for (Json::ArrayIndex m = 0; m < meshes.size(); ++m)
    {
      const Json::Value& primitives = Array(meshes[m], "primitives");
      for (Json::ArrayIndex p = 0; p < primitives.size(); ++p)
      {
        const std::string where = Item("meshes", m) + "." + Item("primitives", p);
        const Json::Value& attributes = primitives[p]["attributes"];
        if (!attributes.isObject() || !attributes.isMember("POSITION"))
        {
          throw Problem(where + " has no POSITION attribute");
        }
        for (const auto& name : attributes.getMemberNames())
        {
          Reference(this->Root, attributes, name.c_str(), "accessors", where + ".attributes");
        }
        for (const Json::Value& target : Array(primitives[p], "targets"))
        {
          for (const auto& name : target.getMemberNames())
          {
            Reference(this->Root, target, name.c_str(), "accessors", where + ".targets");
          }
        }
        Reference(this->Root, primitives[p], "indices", "accessors", where);
        Reference(this->Root, primitives[p], "material", "materials", where);
        if (Number(primitives[p], "mode", 4, where) > 6)
        {
          throw Problem(where + ": 'mode' is not a glTF primitive mode");
        }
      }
    }
  }

  void Nodes()
  {
    const Json::Value& nodes = Array(this->Root, "nodes");
    for (Json::ArrayIndex i = 0; i < nodes.size(); ++i)
    {
      const std::string where = Item("nodes", i);
      Reference(this->Root, nodes[i], "mesh", "meshes", where);
      Reference(this->Root, nodes[i], "skin", "skins", where);
      Reference(this->Root, nodes[i], "camera", "cameras", where);
      this->NodeList(nodes[i], "children", where);
    }
    // A node that is its own ancestor would send a reader round the cycle for ever.
    std::vector<int> state(nodes.size(), 0); // 0 unseen, 1 on the path, 2 done
    for (Json::ArrayIndex i = 0; i < nodes.size(); ++i)
    {
      this->Acyclic(i, state);
    }
    const Json::Value& skins = Array(this->Root, "skins");
    for (Json::ArrayIndex i = 0; i < skins.size(); ++i)
    {
      Reference(this->Root, skins[i], "inverseBindMatrices", "accessors", Item("skins", i));
      Reference(this->Root, skins[i], "skeleton", "nodes", Item("skins", i));
      this->NodeList(skins[i], "joints", Item("skins", i));
    }
    const Json::Value& scenes = Array(this->Root, "scenes");
    for (Json::ArrayIndex i = 0; i < scenes.size(); ++i)
    {
      this->NodeList(scenes[i], "nodes", Item("scenes", i));
    }
    Reference(this->Root, this->Root, "scene", "scenes", "the file");
  }

  void NodeList(const Json::Value& object, const char* key, const std::string& where)
  {
    const Json::Value& list = Array(object, key);
    for (Json::ArrayIndex i = 0; i < list.size(); ++i)
    {
      Json::Value holder(Json::objectValue);
      holder["node"] = list[i];
      Reference(this->Root, holder, "node", "nodes", where + "." + key);
    }
  }

  // Depth first with a stack of its own: a deep hierarchy must not exhaust the call stack.
  void Acyclic(Json::ArrayIndex start, std::vector<int>& state)
  {
    std::vector<std::pair<Json::ArrayIndex, Json::ArrayIndex>> path; // node, next child
    const auto enter = [&](Json::ArrayIndex node) {
      if (state[node] == 1)
      {
        throw Problem(Item("nodes", node) + " is its own ancestor");
      }
      if (state[node] == 0)
      {
        state[node] = 1;
        path.emplace_back(node, 0);
      }
    };
    enter(start);
    while (!path.empty())
    {
      auto& [node, next] = path.back();
      const Json::Value& children = Array(this->Root["nodes"][node], "children");
      if (next < children.size())
      {
        enter(children[next++].asUInt());
        continue;
      }
      state[node] = 2;
      path.pop_back();
    }
  }

  void Animations()
  {
    const Json::Value& animations = Array(this->Root, "animations");
    for (Json::ArrayIndex a = 0; a < animations.size(); ++a)
    {
      const Json::Value& samplers = Array(animations[a], "samplers");
      for (Json::ArrayIndex s = 0; s < samplers.size(); ++s)
      {
        const std::string where = Item("animations", a) + "." + Item("samplers", s);
        if (Reference(this->Root, samplers[s], "input", "accessors", where) < 0 ||
          Reference(this->Root, samplers[s], "output", "accessors", where) < 0)
        {
          throw Problem(where + " needs 'input' and 'output'");
        }
      }
      const Json::Value& channels = Array(animations[a], "channels");
      for (Json::ArrayIndex c = 0; c < channels.size(); ++c)
      {
        const std::string where = Item("animations", a) + "." + Item("channels", c);
        if (Reference(animations[a], channels[c], "sampler", "samplers", where) < 0)
        {
          throw Problem(where + " has no sampler");
        }
        Reference(this->Root, channels[c]["target"], "node", "nodes", where + ".target");
      }
    }
  }

  void Images()
  {
    const Json::Value& images = Array(this->Root, "images");
    for (Json::ArrayIndex i = 0; i < images.size(); ++i)
    {
      const std::string where = Item("images", i);
      Reference(this->Root, images[i], "bufferView", "bufferViews", where);
      if (images[i].isMember("uri"))
      {
        this->UriLength(images[i]["uri"].asString(), where);
      }
    }
    const Json::Value& textures = Array(this->Root, "textures");
    for (Json::ArrayIndex i = 0; i < textures.size(); ++i)
    {
      Reference(this->Root, textures[i], "source", "images", Item("textures", i));
      Reference(this->Root, textures[i], "sampler", "samplers", Item("textures", i));
    }
    const Json::Value& materials = Array(this->Root, "materials");
    for (Json::ArrayIndex i = 0; i < materials.size(); ++i)
    {
      this->TextureReferences(materials[i], Item("materials", i));
    }
  }

  // Every "...Texture": {"index": i} inside a material.
  void TextureReferences(const Json::Value& object, const std::string& where)
  {
    if (!object.isObject())
    {
      return;
    }
    for (const auto& name : object.getMemberNames())
    {
      const Json::Value& member = object[name];
      if (name.size() > 7 && name.compare(name.size() - 7, 7, "Texture") == 0)
      {
        Reference(this->Root, member, "index", "textures", where + "." + name);
      }
      this->TextureReferences(member, where + "." + name);
    }
  }
};
}

bool vtkSubDCheckGLTF(const std::string& fileName, std::string& problem)
{
  try
  {
    bool readable = false;
    const std::string bytes = ReadAll(fileName, readable);
    if (!readable)
    {
      throw Problem("cannot read the file");
    }
    Size binarySize = 0;
    const std::string text = JsonText(bytes, binarySize);
    Json::Value root;
    Json::CharReaderBuilder builder;
    std::unique_ptr<Json::CharReader> reader(builder.newCharReader());
    std::string errors;
    if (!reader->parse(text.data(), text.data() + text.size(), &root, &errors) || !root.isObject())
    {
      throw Problem("not glTF: the JSON does not parse (" + errors + ")");
    }
    const Json::Value& version = root["asset"]["version"];
    if (!version.isString() || version.asString().compare(0, 2, "2.") != 0)
    {
      throw Problem("not glTF 2.0: 'asset.version' is missing or not 2.x");
    }
    const auto slash = fileName.find_last_of('/');
    Checker checker{ root, slash == std::string::npos ? "" : fileName.substr(0, slash + 1), binarySize, {}, {} };
    checker.Buffers();
    checker.BufferViews();
    checker.Accessors();
    checker.Meshes();
    checker.Nodes();
    checker.Animations();
    checker.Images();
    return true;
  }
  catch (const Problem& failure)
  {
    problem = failure.what();
  }
  catch (const Json::Exception& failure)
  {
    problem = std::string("malformed glTF: ") + failure.what();
  }
  return false;
}
