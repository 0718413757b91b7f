/*!
\ingroup PkgPenroseDelaunayTriangulation2Concepts
\cgalConcept

The geometric traits of `CGAL::Penrose_importance_sampler`. The sampler
computes with doubles internally and needs from the traits only what it takes
to read the region and to hand points to the density and to the user.

\cgalHasModelsBegin
\cgalHasModelsBare{All models of the `Kernel` concept}
\cgalHasModelsEnd
*/
class PenroseImportanceSamplerTraits_2
{
public:
  /// A number type convertible with `CGAL::to_double()` and constructible from `double`.
  typedef unspecified_type FT;
  /// The type of the samples and of the density's argument.
  typedef unspecified_type Point_2;
  /// The type of the region, an axis-parallel rectangle.
  typedef unspecified_type Iso_rectangle_2;

  /// `Point_2 operator()(FT x, FT y)`
  typedef unspecified_type Construct_point_2;
  /// `FT operator()(const Point_2&)`
  typedef unspecified_type Compute_x_2;
  /// `FT operator()(const Point_2&)`
  typedef unspecified_type Compute_y_2;
  /// `Point_2 operator()(const Iso_rectangle_2& r, int i)`: vertex 0 is the lower left, 2 the upper right corner.
  typedef unspecified_type Construct_vertex_2;
  /// `Iso_rectangle_2 operator()(const Point_2& lower_left, const Point_2& upper_right)`
  typedef unspecified_type Construct_iso_rectangle_2;

  /// \name Operations
  /// @{

  /// A `Construct_point_2` object.
  Construct_point_2 construct_point_2_object() const;
  /// A `Compute_x_2` object.
  Compute_x_2 compute_x_2_object() const;
  /// A `Compute_y_2` object.
  Compute_y_2 compute_y_2_object() const;
  /// A `Construct_vertex_2` object.
  Construct_vertex_2 construct_vertex_2_object() const;
  /// A `Construct_iso_rectangle_2` object.
  Construct_iso_rectangle_2 construct_iso_rectangle_2_object() const;
  /// @}
};
