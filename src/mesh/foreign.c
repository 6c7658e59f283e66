/* Mesh and scene formats that cg does not read, told apart by their first
 * bytes or by the file's extension, so that a user who passes one gets its
 * name instead of a parse error from whichever reader the bytes resemble
 * (VTK and USDA files start with '#', an OBJ comment).  glTF, which cg reads,
 * is told by mesh_looks_like_gltf_json and the "glTF" magic. */
#include "internal.h"

#include <strings.h>

typedef struct foreign_magic {
    const char *bytes; /* at offset 0 */
    size_t length;
    const char *format;
} foreign_magic;

static const foreign_magic magics[] = {
    {"Kaydara FBX Binary", 18, "an FBX file (.fbx)"},
    {"; FBX", 5, "an FBX file (.fbx)"},
    {"BLENDER", 7, "a Blender file (.blend)"},
    {"PXR-USDC", 8, "a USD file (.usdc)"},
    {"#usda", 5, "a USD file (.usda)"},
    {"#VRML", 5, "a VRML file (.wrl)"},
    {"# vtk DataFile", 14, "a VTK file (.vtk)"},
    {"xof ", 4, "a DirectX file (.x)"},
    {"Ogawa", 5, "an Alembic file (.abc)"},
    {"ISO-10303-21", 12, "a STEP file (.step)"},
    {"//Maya ASCII", 12, "a Maya ASCII file (.ma)"},
    {"3D Geometry File Format", 23, "a Rhino file (.3dm)"},
    {"PK\3\4", 4, "a ZIP archive (such as .3mf, .usdz or .zip)"},
    {"*3DSMAX_ASCIIEXPORT", 19, "an ASCII Scene Export file (.ase)"},
    {"AC3D", 4, "an AC3D file (.ac)"},
    {"HMP4", 4, "a 3D GameStudio terrain (.hmp)"},
    {"HMP5", 4, "a 3D GameStudio terrain (.hmp)"},
    {"HMP7", 4, "a 3D GameStudio terrain (.hmp)"},
    {"IDPO", 4, "a Quake model (.mdl)"},
    {"IDST", 4, "a Half-Life model (.mdl)"},
    {"IDSQ", 4, "a Half-Life model (.mdl)"},
    {"IDP2", 4, "a Quake II model (.md2)"},
    {"IDP3", 4, "a Quake III model (.md3)"},
    {"IDPC", 4, "a Return to Castle Wolfenstein model (.mdc)"},
    {"MS3D000000", 10, "a MilkShape 3D file (.ms3d)"},
    {"INTERQUAKEMODEL", 15, "an Inter-Quake model (.iqm)"},
    {"BB3D", 4, "a Blitz3D file (.b3d)"},
    {"HIERARCHY", 9, "a BioVision motion file (.bvh)"},
    {"Caligari ", 9, "a Caligari trueSpace file (.cob)"},
    {"quick3Do", 8, "a Quick3D object (.q3o)"},
    {"quick3Ds", 8, "a Quick3D scene (.q3s)"},
    {"3DMO", 4, "a Model 3D file (.m3d)"},
    {"3dmodel", 7, "a Model 3D file (.m3d)"},
};

typedef struct foreign_extension {
    const char *suffix;
    const char *format;
} foreign_extension;

static const foreign_extension extensions[] = {
    {".fbx", "an FBX file (.fbx)"},
    {".3ds", "a 3D Studio file (.3ds)"},
    {".dae", "a COLLADA file (.dae)"},
    {".blend", "a Blender file (.blend)"},
    {".usd", "a USD file (.usd)"},
    {".usda", "a USD file (.usda)"},
    {".usdc", "a USD file (.usdc)"},
    {".usdz", "a USD file (.usdz)"},
    {".abc", "an Alembic file (.abc)"},
    {".3mf", "a 3MF file (.3mf)"},
    {".amf", "an AMF file (.amf)"},
    {".x3d", "an X3D file (.x3d)"},
    {".wrl", "a VRML file (.wrl)"},
    {".vtk", "a VTK file (.vtk)"},
    {".vtp", "a VTK file (.vtp)"},
    {".vtu", "a VTK file (.vtu)"},
    {".step", "a STEP file (.step)"},
    {".stp", "a STEP file (.stp)"},
    {".iges", "an IGES file (.iges)"},
    {".igs", "an IGES file (.igs)"},
    {".ifc", "an IFC file (.ifc)"},
    {".dxf", "a DXF file (.dxf)"},
    {".lwo", "a LightWave file (.lwo)"},
    {".x", "a DirectX file (.x)"},
    {".ma", "a Maya ASCII file (.ma)"},
    {".mb", "a Maya binary file (.mb)"},
    {".max", "a 3ds Max file (.max)"},
    {".3dm", "a Rhino file (.3dm)"},
    {".skp", "a SketchUp file (.skp)"},
    {".ms3d", "a MilkShape 3D file (.ms3d)"},
    {".md2", "a Quake II model (.md2)"},
    {".md3", "a Quake III model (.md3)"},
    {".md5mesh", "a Doom 3 model (.md5mesh)"},
    {".ase", "an ASCII Scene Export file (.ase)"},
    {".smd", "a Source model (.smd)"},
    {".b3d", "a Blitz3D file (.b3d)"},
    {".mdl", "a Quake or Half-Life model (.mdl)"},
    {".mdc", "an MDC model (.mdc)"},
    {".hmp", "a 3D GameStudio terrain (.hmp)"},
    {".lws", "a LightWave scene (.lws)"},
    {".lxo", "a Modo file (.lxo)"},
    {".nff", "a Neutral File Format file (.nff)"},
    {".irr", "an Irrlicht scene (.irr)"},
    {".irrmesh", "an Irrlicht mesh (.irrmesh)"},
    {".ac", "an AC3D file (.ac)"},
    {".acc", "an AC3D file (.acc)"},
    {".ac3d", "an AC3D file (.ac3d)"},
    {".cob", "a Caligari trueSpace file (.cob)"},
    {".scn", "a Caligari trueSpace scene (.scn)"},
    {".m3d", "a Model 3D file (.m3d)"},
    {".a3d", "a Model 3D file (.a3d)"},
    {".zgl", "a zipped XGL file (.zgl)"},
    {".xgl", "an XGL file (.xgl)"},
    {".ogex", "an OpenGEX file (.ogex)"},
    {".q3o", "a Quick3D object (.q3o)"},
    {".q3s", "a Quick3D scene (.q3s)"},
    {".bvh", "a BioVision motion file (.bvh)"},
    {".ter", "a Terragen terrain (.ter)"},
    {".3d", "an Unreal mesh (.3d)"},
    {".uc", "an Unreal script (.uc)"},
    {".csm", "a CharacterStudio motion file (.csm)"},
    {".sib", "a Silo file (.sib)"},
    {".iqm", "an Inter-Quake model (.iqm)"},
    {".jt", "a JT file (.jt)"},
    {".md5anim", "a Doom 3 animation (.md5anim)"},
    {".mot", "a motion file (.mot)"},
};

/* Searches the first `limit` bytes for a word (XML root elements). */
static int contains(const unsigned char *bytes, size_t size, size_t limit, const char *word)
{
    size_t n = strlen(word), end = size < limit ? size : limit;
    for (size_t i = 0; i + n <= end; i++)
        if (memcmp(bytes + i, word, n) == 0)
            return 1;
    return 0;
}

int mesh_looks_like_gltf_json(const unsigned char *bytes, size_t size)
{
    size_t first = 0;
    if (size >= 3 && memcmp(bytes, "\xEF\xBB\xBF", 3) == 0)
        first = 3;
    while (first < size && first < 64
           && (bytes[first] == ' ' || bytes[first] == '\t' || bytes[first] == '\n'
               || bytes[first] == '\r'))
        first++;
    return first < size && bytes[first] == '{' && contains(bytes, size, 4096, "\"asset\"");
}

const char *mesh_foreign_by_content(const unsigned char *bytes, size_t size)
{
    for (size_t i = 0; i < sizeof magics / sizeof magics[0]; i++)
        if (size >= magics[i].length && memcmp(bytes, magics[i].bytes, magics[i].length) == 0)
            return magics[i].format;
    if (size >= 5 && memcmp(bytes, "<?xml", 5) == 0) {
        if (contains(bytes, size, 4096, "<COLLADA"))
            return "a COLLADA file (.dae)";
        if (contains(bytes, size, 4096, "<X3D"))
            return "an X3D file (.x3d)";
        if (contains(bytes, size, 4096, "<VTKFile"))
            return "a VTK XML file (.vtp, .vtu)";
        if (contains(bytes, size, 4096, "<amf"))
            return "an AMF file (.amf)";
        if (contains(bytes, size, 4096, "<irr_scene"))
            return "an Irrlicht scene (.irr)";
        if (contains(bytes, size, 4096, "<mesh") && contains(bytes, size, 4096, "irrmesh"))
            return "an Irrlicht mesh (.irrmesh)";
    }
    /* LightWave: an IFF FORM whose type is LWO2, LWOB or LWLO */
    if (size >= 12 && memcmp(bytes, "FORM", 4) == 0
        && (memcmp(bytes + 8, "LWO2", 4) == 0 || memcmp(bytes + 8, "LWOB", 4) == 0
            || memcmp(bytes + 8, "LWLO", 4) == 0))
        return "a LightWave object (.lwo)";
    if (size >= 4 && memcmp(bytes, "LWSC", 4) == 0)
        return "a LightWave scene (.lws)";
    /* 3D Studio: main chunk 0x4d4d whose 32-bit length is the file's size */
    if (size >= 6 && bytes[0] == 0x4d && bytes[1] == 0x4d) {
        uint32_t length = (uint32_t)bytes[2] | (uint32_t)bytes[3] << 8 | (uint32_t)bytes[4] << 16
                          | (uint32_t)bytes[5] << 24;
        if (length == size)
            return "a 3D Studio file (.3ds)";
    }
    return NULL;
}

const char *mesh_foreign_by_name(const char *name)
{
    if (!name)
        return NULL;
    size_t length = strlen(name);
    if (length >= 3 && strcasecmp(name + length - 3, ".gz") == 0)
        length -= 3;
    for (size_t i = 0; i < sizeof extensions / sizeof extensions[0]; i++) {
        size_t n = strlen(extensions[i].suffix);
        if (length > n && strncasecmp(name + length - n, extensions[i].suffix, n) == 0)
            return extensions[i].format;
    }
    return NULL;
}
