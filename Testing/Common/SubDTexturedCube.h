// A unit cube with a cross unwrap, as an OBJ file's text: the four sides in a strip of texture
// space (one seam where the strip closes), the top and bottom caps attached to side 0, so seams
// run along seven of its edges.
#ifndef SubDTexturedCube_h
#define SubDTexturedCube_h

#include <string>

namespace subdtest
{
inline std::string CrossUnwrappedCubeOBJ()
{
  std::string text = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n";
  const char* vt[] = { "0 0", "1 0", "2 0", "3 0", "4 0", "0 1", "1 1", "2 1", "3 1", "4 1", "0 2", "1 2", "0 -1",
    "1 -1" };
  for (const char* t : vt)
    text += std::string("vt ") + t + "\n";
  text += "f 1/1 2/2 6/7 5/6\nf 2/2 3/3 7/8 6/7\nf 3/3 4/4 8/9 7/8\nf 4/4 1/5 5/10 8/9\n" // sides
          "f 5/6 6/7 7/12 8/11\nf 1/1 4/13 3/14 2/2\n";                                 // caps
  return text;
}
}

#endif
